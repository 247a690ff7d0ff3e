"""The learned segmenter's box-only upscale + one-surface cut must give exactly the whole-frame way's mask."""

import cv2
import numpy as np
import pytest
from scipy import ndimage

from spark_core.perception.frame import CameraFrame
from spark_core.perception.learned.segmenter import DEPTH_SPREAD_M, _one_surface, _one_surface_upscaled


def _frame(H: int, W: int, rng: np.random.Generator) -> CameraFrame:
    depth = rng.uniform(0.8, 1.2, (H, W)).astype(np.float32)
    depth[rng.random((H, W)) < 0.1] += 4 * DEPTH_SPREAD_M  # the wall behind, where an upscaled mask spills
    depth[rng.random((H, W)) < 0.05] = np.nan  # no depth
    K = np.array([[500.0, 0, W / 2], [0, 500.0, H / 2], [0, 0, 1]])
    return CameraFrame("agentview", np.zeros((H, W, 3), np.uint8), depth, K, np.eye(4))


@pytest.mark.parametrize("full_shape, net_shape", [((48, 64), (24, 32)), ((45, 64), (22, 32))])
def test_box_only_equals_whole_frame(full_shape, net_shape):
    rng = np.random.default_rng(full_shape[0])
    frame = _frame(*full_shape, rng)
    small = cv2.dilate((rng.random(net_shape) < 0.04).astype(np.uint8), np.ones((3, 3), np.uint8))
    n, comp = cv2.connectedComponents(small, connectivity=4)
    assert n > 3
    for k, box in enumerate(ndimage.find_objects(comp, max_label=n - 1), start=1):
        want = _one_surface(
            cv2.resize((comp == k).astype(np.uint8), full_shape[::-1], interpolation=cv2.INTER_NEAREST).astype(bool),
            frame,
        )
        got = _one_surface_upscaled(comp[box] == k, box, frame, full_shape, net_shape)
        assert got.dtype == bool and got.shape == full_shape
        np.testing.assert_array_equal(got, want)


def test_a_box_without_depth_keeps_the_whole_upscaled_mask():
    rng = np.random.default_rng(0)
    frame = _frame(48, 64, rng)
    frame.depth_m[:] = np.nan
    comp = np.zeros((24, 32), np.int32)
    comp[5:9, 10:14] = 1
    box = ndimage.find_objects(comp)[0]
    got = _one_surface_upscaled(comp[box] == 1, box, frame, (48, 64), (24, 32))
    assert got.sum() == 4 * 16 and got[10:18, 20:28].all()
