"""Masks refined by depth at camera resolution (learned/refine.py). Synthetic frame: a camera 1 m in front of a
bottle, looking along world +x from 10 cm above the table top (z = 0); 1 px = 2 mm at the bottle; image row v is
world height 0.1 - (v - 120) * 0.002 m."""

from __future__ import annotations

import numpy as np

from spark_core.perception.frame import CameraFrame
from spark_core.perception.learned.refine import grow_by_depth

H, W = 240, 320


def _scene():
    K = np.array([[500.0, 0, W / 2], [0, 500.0, H / 2], [0, 0, 1]])
    T = np.eye(4)
    T[:3, :3] = np.array([[0.0, 0, 1], [-1, 0, 0], [0, -1, 0]])  # camera x = -world y, y = -world z, z = world x
    T[2, 3] = 0.1
    depth = np.full((H, W), 3.0)  # the wall behind
    depth[170:, :] = 1.2  # the table top behind the bottle, below the camera (rows under z = 0)
    depth[70:170, 140:180] = 1.0  # the bottle's body, z 0 .. 0.2 m
    depth[50:70, 155:165] = 1.0  # its neck, z 0.2 .. 0.24 m: 10 px wide
    frame = CameraFrame("front", np.zeros((H, W, 3), np.uint8), depth.astype(np.float32), K, T)
    vs, us = np.mgrid[:H, :W]
    height = frame.backproject(us.ravel().astype(float), vs.ravel().astype(float), depth.ravel())[:, 2].reshape(H, W)
    return frame, depth, height


def test_a_lost_neck_grows_back_and_nothing_else_is_taken():
    frame, depth, height = _scene()
    body = np.zeros((H, W), bool)
    body[70:170, 140:180] = True  # the network found the body and lost the neck (called it background)
    free = ~body
    grown = grow_by_depth(body, free, depth, height, table_z_m=0.0)
    assert grown[50:70, 155:165].all()  # the neck is back
    assert (grown & ~body).sum() == 20 * 10  # nothing but the neck: not the wall, not the table
    # pixels the network gave another object are never taken, even where the depth continues
    other = np.zeros((H, W), bool)
    other[50:60, 155:165] = True
    assert not (grow_by_depth(body, free & ~other, depth, height, 0.0) & other).any()


def test_growth_only_climbs_and_stays_above_the_table():
    frame, depth, height = _scene()
    neck = np.zeros((H, W), bool)
    neck[50:70, 155:165] = True  # only the neck found: the body below it is not grown into (growth climbs)
    assert (grow_by_depth(neck, ~neck, depth, height, 0.0) == neck).all()
    body = np.zeros((H, W), bool)
    body[70:170, 140:180] = True
    assert (grow_by_depth(body, ~body, depth, height, table_z_m=0.5) == body).all()  # all of it under "the table"
