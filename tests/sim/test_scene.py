"""Object library, seeded collision-free placement, and cameras (RGB, metric depth, ids, K, extrinsics)."""

import numpy as np
import pytest

from spark_core.control.panda import panda
from spark_core.sim.objects import KINDS
from spark_core.sim.scene import GRIPPER_CLEARANCE_M, ObjectRequest, build_scene
from spark_core.sim.tasks import BUILTIN


def test_object_library_has_labelled_described_objects():
    assert len(KINDS) >= 15
    for kind, make in KINDS.items():
        spec = make("red")
        assert spec.description and spec.category and spec.footprint_m > 0, kind
    assert "drawer handle" in KINDS["cabinet"]("brown").parts and "knob" in KINDS["stove"]("grey").parts


def test_placement_is_seeded_and_collision_free():
    reqs = [ObjectRequest(f"block {i}", "block", "red", (0.35, 0.65), (-0.3, 0.3)) for i in range(5)]
    a = build_scene({"right": (panda(), np.eye(4))}, reqs, seed=4)
    b = build_scene({"right": (panda(), np.eye(4))}, reqs, seed=4)
    c = build_scene({"right": (panda(), np.eye(4))}, reqs, seed=5)
    pa = np.array([o.position_m for o in a.objects.values()])
    assert np.array_equal(pa, np.array([o.position_m for o in b.objects.values()]))
    assert not np.array_equal(pa, np.array([o.position_m for o in c.objects.values()]))
    for i in range(5):
        for j in range(i):
            assert (
                np.linalg.norm(pa[i, :2] - pa[j, :2])
                > 2 * a.objects["block 0"].spec.footprint_m + GRIPPER_CLEARANCE_M - 1e-9
            )


def test_impossible_placement_says_which_object():
    reqs = [ObjectRequest(f"bowl {i}", "bowl", "white", (0.5, 0.52), (0.0, 0.02)) for i in range(2)]
    with pytest.raises(RuntimeError, match="could not place 'bowl 1'|could not place 'bowl 0'"):
        build_scene({"right": (panda(), np.eye(4))}, reqs, seed=0)


@pytest.fixture(scope="module")
def world():
    w = BUILTIN["stack_two"].make_world(0)
    yield w
    w.close()


def test_camera_frame_contents(world):
    f = world.render("agentview")
    assert f.rgb.shape == (480, 640, 3) and f.rgb.dtype == np.uint8
    assert f.depth_m.shape == (480, 640) and 0.5 < float(np.median(f.depth_m)) < 3.0
    assert {f.labels[i] for i in np.unique(f.object_ids) if i} == {"red block", "blue block"}
    assert f.K[0, 0] == pytest.approx(f.K[1, 1]) and f.K[0, 2] == pytest.approx(319.5)


def test_depth_back_projects_onto_the_object(world):
    """Pixels of the red block, lifted to 3D with K, depth and T_world_camera, land on the block's surface."""
    f = world.render("agentview")
    rid = next(i for i, label in f.labels.items() if label == "red block")
    v, u = np.nonzero(f.object_ids == rid)
    z = f.depth_m[v, u]
    pts_cam = np.stack([(u - f.K[0, 2]) * z / f.K[0, 0], (v - f.K[1, 2]) * z / f.K[1, 1], z], axis=1)
    pts = pts_cam @ f.T_world_camera[:3, :3].T + f.T_world_camera[:3, 3]
    lo, hi = world.body_aabb("red block")
    inside = np.all((pts > lo - 0.004) & (pts < hi + 0.004), axis=1)
    assert inside.mean() > 0.95


def test_rendering_is_on_demand(world):
    t = world.sim_time_s
    world.render("side")
    assert world.sim_time_s == t  # rendering never steps physics


def test_trajectory_recorder_samples_at_the_control_rate():
    from spark_core.sim.world import CONTROL_DT_S, TrajectoryRecorder

    w = BUILTIN["lift_block"].make_world(1)
    w.recorder = TrajectoryRecorder()
    w.settle(0.5)
    ts = [r[0] for r in w.recorder.rows]
    assert len(ts) == 50 and np.allclose(np.diff(ts), CONTROL_DT_S)
    assert len(w.recorder.rows[0][2]) == 7  # seven arm joints per row
    w.close()
