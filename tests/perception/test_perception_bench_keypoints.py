"""The perception bench's reference keypoint: the trial resolver's lifting on the renderer's true masks."""

from __future__ import annotations

import numpy as np
import pytest

from spark_core.bench.perception_bench import CAMERAS, true_mask_keypoint
from spark_core.perception.frame import CameraFrame
from spark_core.perception.learned.dataset import geom_tables, render_labelled
from spark_core.perception.resolver import PerceptionResolver
from spark_core.perception.sim_segmenter import SimSegmenter
from spark_core.sim.cameras import label_table
from spark_core.sim.tasks import BUILTIN


@pytest.fixture(scope="module")
def drawer_world():
    world = BUILTIN["close_drawer"].make_world(0)
    yield world
    world.close()


def _views(world):
    tables = geom_tables(world)
    views = []
    for cam in CAMERAS:
        lf = render_labelled(world, cam, tables)
        views.append((CameraFrame(cam, lf.rgb, lf.depth_m, lf.K, lf.T_world_camera), lf.instance))
    return views


def test_true_mask_keypoint_is_what_the_resolver_gives_with_perfect_masks(drawer_world):
    views = _views(drawer_world)
    ids = {label: i for i, label in label_table(drawer_world)[0].items()}
    oracle = PerceptionResolver(drawer_world, SimSegmenter(drawer_world.scene.catalog()), cameras=CAMERAS)
    for label in ("red block", "cabinet drawer"):
        ref = true_mask_keypoint(label, ids[label], views)
        assert ref is not None
        assert np.linalg.norm(oracle.resolve(label).position_m - ref) < 0.005, label


def test_true_mask_keypoint_follows_the_mask_not_the_label(drawer_world):
    views = _views(drawer_world)
    ids = {label: i for i, label in label_table(drawer_world)[0].items()}
    block = true_mask_keypoint("red block", ids["red block"], views)
    other = true_mask_keypoint("red block", ids["cabinet"], views)  # a wrong mask gives a wrong point
    assert block is not None and other is not None
    assert np.linalg.norm(block - other) > 0.05
    assert true_mask_keypoint("red block", 10_000, views) is None  # an instance no view sees
