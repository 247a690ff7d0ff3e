"""The paper's bimanual slots on the two-Panda cell: `place_with_arm` without a target sets the held object down
where the hand is; `pick_with_arm` honours force, expected width and an angled approach."""

import numpy as np
import pytest

from spark_core.execution import Executor
from spark_core.execution.primitives import PrimitiveLibrary
from spark_core.execution.primitives.pick_place import ANGLED_LEAN_RAD
from spark_core.grammar import parse_plan
from spark_core.perception.privileged import PrivilegedResolver
from spark_core.sim.tasks import TASKS

PLAN = """
task: move the red block 6 cm forward and set it down
tree:
  type: sequence
  children:
    - type: pick_with_arm
      params: {{arm: left, keypoint_label: red block, force: 40, target_width: 0.04, prefer_angled: {angled}}}
    - type: move_relative
      params: {{arm: left, dx: 0.06}}
    - type: place_with_arm
      params: {{arm: left}}
"""


def _run(plan: str):
    world = TASKS["sort_bimanual"].make_world(0, None)
    resolver = PrivilegedResolver(world)
    start = resolver.resolve("red block").position_m.copy()
    hand: dict[str, tuple] = {}  # node path -> (TCP position, TCP rotation) when it started

    def on_event(e):
        if e.kind == "started":
            tcp = world.tcp_pose("left")
            hand.setdefault(e.node_path, (tcp.position_m.copy(), tcp.rotation.copy()))

    ex = Executor(PrimitiveLibrary(world, resolver, seed=0), resolver)
    ex.bus.subscribe(on_event)
    result = ex.run(parse_plan(plan))
    world.settle(0.3)
    resolver.refresh()
    return world, resolver, start, hand, result


@pytest.mark.parametrize("angled", [False, True])
def test_place_with_arm_without_a_label_sets_the_object_down_where_the_hand_is(angled):
    world, resolver, start, hand, result = _run(PLAN.format(angled=str(angled).lower()))
    try:
        assert result.outcome == "success", result.reason
        block = resolver.resolve("red block")
        tcp_xy = hand["tree.children[2]"][0][:2]  # where the hand was when place_with_arm started
        assert np.linalg.norm(block.position_m[:2] - tcp_xy) < 0.015
        assert np.linalg.norm(block.position_m[:2] - start[:2]) > 0.045  # it was carried, not dropped back
        assert block.position_m[2] == pytest.approx(start[2], abs=0.005)  # resting on the table, upright
        assert not world.pinched_bodies("left")
        held_z = hand["tree.children[1]"][1][:, 2]  # the fingers' direction after the pick
        lean = float(np.arccos(np.clip(-held_z[2], -1.0, 1.0)))
        assert lean == pytest.approx(ANGLED_LEAN_RAD if angled else 0.0, abs=0.1)
    finally:
        world.close()


def test_place_with_arm_with_nothing_held_fails_without_moving():
    world, _, _, _, result = _run("task: t\ntree: {type: place_with_arm, params: {arm: right}}")
    try:
        assert result.outcome == "failure" and "nothing in the gripper to set down" in result.reason
    finally:
        world.close()


def test_pick_with_arm_checks_the_expected_width():
    world, _, _, _, result = _run(
        "task: t\ntree: {type: pick_with_arm, params: {arm: left, keypoint_label: red block, target_width: 0.08}}"
    )
    try:
        assert result.outcome == "failure" and "expected about 80 mm" in result.reason
    finally:
        world.close()
