"""Parallel arm branches run concurrently, rendezvous at sync barriers and join before the next node."""

import time

from spark_core.execution import Executor, FailureKind
from spark_core.grammar import parse_plan
from tests.doubles.kinematic_world import KinematicResolver, KinematicWorld

OBJECTS = {
    "fork": [0.5, 0.2, 0.01],
    "spoon": [0.5, -0.2, 0.01],
    "left tray": [0.3, 0.35, 0.01],
    "right tray": [0.3, -0.35, 0.01],
}

SORT = """
task: sort fork and spoon
tree:
  type: sequence
  children:
    - type: parallel
      children:
        - type: sequence
          arm: left
          children:
            - primitive: pick_with_arm
              params: {keypoint_label: fork}
            - primitive: sync_barrier
              params: {name: carried}
            - primitive: place_with_arm
              params: {target_label: left tray}
        - type: sequence
          arm: right
          children:
            - primitive: pick_with_arm
              params: {keypoint_label: spoon}
            - primitive: sync_barrier
              params: {name: carried}
            - primitive: place_with_arm
              params: {target_label: right tray}
    - primitive: go_home
      arm: left
"""


def run(plan_text, delay=0.05, unreachable=()):
    world = KinematicWorld(OBJECTS, arms=("left", "right"), wall_delay_s=delay, unreachable=set(unreachable))
    ex = Executor(world, KinematicResolver(world))
    return world, ex.run(parse_plan(plan_text))


def span(result, path):
    ev = {e.kind: e.t for e in result.events if e.node_path == path}
    return ev["started"], ev.get("succeeded", ev.get("failed"))


def test_branches_overlap_in_time_and_join():
    world, result = run(SORT)
    assert result.outcome == "success", result.reason
    l0, l1 = span(result, "tree.children[0].children[0]")
    r0, r1 = span(result, "tree.children[0].children[1]")
    assert l0 < r1 and r0 < l1, "branches did not overlap"
    # the first primitives of both arms were in flight at the same time
    lp = span(result, "tree.children[0].children[0].children[0]")
    rp = span(result, "tree.children[0].children[1].children[0]")
    assert lp[0] < rp[1] and rp[0] < lp[1]
    # implicit barrier: the node after the parallel starts after both branches finished
    home_start, _ = span(result, "tree.children[1]")
    assert home_start >= max(l1, r1)
    assert world.objects["fork"][1] > 0.3 and world.objects["spoon"][1] < -0.3
    arms = {(a, p) for a, p, _ in world.log}
    assert ("left", "pick_with_arm") in arms and ("right", "pick_with_arm") in arms


def test_sync_barrier_waits_for_the_slower_branch():
    world = KinematicWorld(OBJECTS, arms=("left", "right"), wall_delay_s=0.0)
    slow = world.perform

    def perform(call, kps, arm, timeout_s):
        if arm == "right" and call.primitive == "pick_with_arm":
            time.sleep(0.3)
        return slow(call, kps, arm, timeout_s)

    world.perform = perform
    result = Executor(world, KinematicResolver(world)).run(parse_plan(SORT))
    assert result.outcome == "success"
    left_sync_done = span(result, "tree.children[0].children[0].children[1]")[1]
    right_pick_done = span(result, "tree.children[0].children[1].children[0]")[1]
    assert left_sync_done >= right_pick_done


def test_failing_branch_releases_the_other_barrier_and_fails_the_parallel():
    t0 = time.monotonic()
    world, result = run(SORT, delay=0.0, unreachable=["fork"])
    assert time.monotonic() - t0 < 5.0  # no 20 s barrier timeout
    assert result.outcome == "failure" and result.failure is FailureKind.KINEMATIC_LIMIT
    assert result.failed_node == "tree.children[0].children[0].children[0]"
    right_sync = result.nodes["tree.children[0].children[1].children[1]"]
    assert right_sync.status == "failed" and "another branch failed" in right_sync.reason
    assert (
        world.held["right"] == "spoon" and result.nodes["tree.children[0].children[1].children[2]"].status == "pending"
    )
    assert result.nodes["tree.children[0]"].status == "failed"
    assert result.nodes["tree.children[1]"].status == "pending"


def test_both_arm_primitive_needs_two_arms():
    world = KinematicWorld(OBJECTS)  # one arm
    result = Executor(world, KinematicResolver(world)).run(
        parse_plan("task: t\ntree: {primitive: bimanual_lift, params: {keypoint_label: fork}}")
    )
    assert result.failure is FailureKind.PLANNER and "needs two arms" in result.reason


def test_handoff_runs_on_two_arms():
    plan = """
task: hand over
tree:
  type: sequence
  children:
    - primitive: pick_with_arm
      arm: left
      params: {keypoint_label: fork}
    - primitive: handoff
      params: {keypoint_label: fork, from_arm: left, to_arm: right}
"""
    world, result = run(plan, delay=0.0)
    assert result.outcome == "success" and world.held == {"left": None, "right": "fork"}
