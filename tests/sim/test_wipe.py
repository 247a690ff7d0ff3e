"""CaP-Bench Wipe: the mounted wiping pad, robosuite's marker bookkeeping, and wiping a trail clean."""

from __future__ import annotations

import numpy as np
import pytest

pytest.importorskip("robosuite", reason="benchmark extras: make bench-deps")

from spark_core.control.pose import Pose, top_down_rotation
from spark_core.execution.primitives import PrimitiveLibrary
from spark_core.execution.primitives.coverage import coverage_strokes
from spark_core.grammar import PrimitiveCall
from spark_core.perception import LabelNotFound
from spark_core.perception.privileged import PrivilegedResolver
from spark_core.sim.tasks import TASKS


@pytest.fixture()
def wipe():
    world = TASKS["Wipe"].make_world(0)
    resolver = PrivilegedResolver(world)
    yield world, resolver, PrimitiveLibrary(world, resolver, seed=0)
    world.close()


def test_the_wiping_pad_is_a_mounted_tool_without_fingers(wipe):
    world, resolver, lib = wipe
    gripper = world.kinematics["right"].robot.gripper
    assert gripper.mounted_tool == "wiping pad" and gripper.tool_size_m == (0.05, 0.12)
    assert world.set_gripper("right", 0.0, 10.0) == 0.0 and world.gripper_width_m("right") == 0.0
    out = lib.perform(PrimitiveCall("grasp", {"force": 10.0}), {}, "right", 5)
    assert not out.ok and "mounted wiping pad" in out.reason


def test_markers_are_wiped_only_under_the_pressed_pad_then_the_dirt_is_gone(wipe):
    world, resolver, lib = wipe
    dirt = resolver.resolve("dirt")
    trail = np.asarray(dirt.detail["footprint_xy_m"])
    assert len(trail) == 100  # one point per marker disc
    strokes, heading = coverage_strokes(trail, 0.09)
    motion = lib.motion["right"]
    hover = [Pose(np.array([*p, 0.015]), top_down_rotation(heading)) for p in strokes]  # pad face 1.5 cm up
    assert motion.move_to(hover[0]).ok
    for p in hover[1:]:
        motion.move_line(p, speed_m_s=0.1)
    assert world.referee.summary.startswith("0 of 100"), world.referee.summary

    out = lib.perform(PrimitiveCall("wipe_area", {"keypoint_label": "dirt"}), {"dirt": dirt}, "right", 180)
    assert out.ok, out.reason
    assert world.referee.summary == "100 of 100 markers wiped"
    assert TASKS["Wipe"].success(world)
    with pytest.raises(LabelNotFound):
        resolver.resolve("dirt")  # wiped markers are transparent: nothing of the dirt is left to find


def test_the_episode_ends_for_good_near_a_joint_limit(wipe):
    world, resolver, lib = wipe
    adr = world.model.joint("robot0_joint7").qposadr[0]
    world.data.qpos[adr] = world.model.jnt_range[world.model.joint("robot0_joint7").id][1] - 0.05
    world.referee.next_t_s = 0.0  # due now: the referee runs once per 50 ms of simulated time
    world.referee(world)
    assert "joint came within 0.1 rad" in world.referee.ended
    world.reset()  # hold where the arm is now, then wipe: robosuite's episode is over, so nothing counts
    lib.perform(
        PrimitiveCall("wipe_area", {"keypoint_label": "dirt", "max_passes": 1}),
        {"dirt": resolver.resolve("dirt")},
        "right",
        180,
    )
    assert world.referee.summary.startswith("0 of 100") and not TASKS["Wipe"].success(world)
