"""Executor core against the kinematic double: event trail, recovery tiers, timeouts, fallback, late binding."""

import asyncio

import numpy as np
import pytest

from spark_core.execution import EventBus, Executor, FailureKind, RecoveryPolicy
from spark_core.grammar import parse_plan
from tests.doubles.kinematic_world import KinematicResolver, KinematicWorld

PICK_PLACE = """
task: put the cube on the plate
tree:
  type: sequence
  children:
    - primitive: move_to_keypoint
      params: {keypoint_label: cube, offset_z: 0.0}
    - primitive: grasp
    - primitive: move_to_keypoint
      params: {keypoint_label: plate, offset_z: 0.05}
    - primitive: release
"""


def make(objects=None, arms=("right",), **kw):
    world = KinematicWorld(objects or {"cube": [0.5, 0.0, 0.02], "plate": [0.5, 0.2, 0.01]}, arms=arms)
    resolver = KinematicResolver(world)
    return world, resolver, Executor(world, resolver, trial_id="t1", **kw)


def trail(result):
    return [(e.node_path, e.kind) for e in result.events]


def test_event_sequence_of_a_clean_run_is_exact():
    world, _, ex = make()
    result = ex.run(parse_plan(PICK_PLACE))
    assert result.outcome == "success" and result.failure is None
    assert trail(result) == [
        ("tree", "started"),
        ("tree.children[0]", "started"),
        ("tree.children[0]", "succeeded"),
        ("tree.children[1]", "started"),
        ("tree.children[1]", "succeeded"),
        ("tree.children[2]", "started"),
        ("tree.children[2]", "succeeded"),
        ("tree.children[3]", "started"),
        ("tree.children[3]", "succeeded"),
        ("tree", "succeeded"),
    ]
    ts = [e.t for e in result.events]
    assert ts == sorted(ts) and [e.seq for e in result.events] == list(range(len(ts)))
    assert all(e.trial_id == "t1" for e in result.events)
    assert result.events[3].detail["primitive"] == "grasp" and result.events[4].detail["object"] == "cube"
    np.testing.assert_allclose(world.objects["cube"], [0.5, 0.2, 0.06])
    # sim time: 0.4 m + 0.1 m... from the double's constant speed, summed over the sequence
    assert result.sim_time_s == pytest.approx(sum(r.sim_time_s for r in result.nodes.values() if r.kind != "sequence"))


def test_recovery_tiers_fire_in_order_then_fail_closed_after_two_retries():
    world, resolver, ex = make()
    world.inject("grasp", n=3, reason="fingers closed on nothing")
    result = ex.run(parse_plan(PICK_PLACE))
    assert result.outcome == "failure"
    assert result.failure is FailureKind.CONTROL and result.failed_node == "tree.children[1]"
    retrying = [e.detail for e in result.events if e.kind == "retrying"]
    assert [(d["attempt"], d["tier"], d["action"]) for d in retrying] == [
        (1, 1, "grasp_perturb"),
        (2, 2, "retract+redetect+reapproach:move_to_keypoint"),
    ]
    grasp = result.nodes["tree.children[1]"]
    assert grasp.attempts == 3 and grasp.retries == 2 and grasp.status == "failed"
    assert grasp.recoveries == ["tier1:grasp_perturb", "tier2:retract+redetect+reapproach:move_to_keypoint"]
    # what the robot did, in order: grasp, perturb, grasp, open + retract 10 cm, re-approach the re-detected cube, grasp
    assert [p for _, p, _ in world.log[1:]] == [
        "grasp",
        "grasp_perturb",
        "grasp",
        "release",
        "move_relative",
        "move_to_keypoint",
        "grasp",
    ]
    assert world.log[5][2]["dz"] == pytest.approx(0.10)
    assert resolver.refreshes == 1
    assert trail(result)[-2:] == [("tree.children[1]", "failed"), ("tree", "failed")]
    assert "tree.children[2]" not in {p for p, _ in trail(result)}


def test_retry_succeeds_after_tier_one():
    world, _, ex = make()
    world.inject("grasp", n=1)
    result = ex.run(parse_plan(PICK_PLACE))
    assert result.outcome == "success"
    assert result.nodes["tree.children[1]"].retries == 1


def test_non_contact_primitive_skips_tier_one():
    world, resolver, ex = make()
    world.inject("move_to_keypoint", n=1, reason="TCP 3 cm off target")
    result = ex.run(parse_plan(PICK_PLACE))
    assert result.outcome == "success"
    (retry,) = [e.detail for e in result.events if e.kind == "retrying"]
    assert retry["tier"] == 2 and resolver.refreshes == 1


def test_recovery_can_be_disabled():
    world, _, ex = make(recovery=RecoveryPolicy(max_retries=0))
    world.inject("grasp", n=1)
    result = ex.run(parse_plan(PICK_PLACE))
    assert result.outcome == "failure" and result.nodes["tree.children[1]"].attempts == 1


def test_timeout_fires_from_simulated_duration():
    world, _, ex = make(recovery=RecoveryPolicy(max_retries=0))
    world.speed_m_s = 0.05  # 0.4 m at 5 cm/s = 8 s > the 4 s timeout of move_to_keypoint
    result = ex.run(parse_plan(PICK_PLACE))
    assert result.failure is FailureKind.TIMEOUT
    assert result.failed_node == "tree.children[0]"
    assert "exceeded its timeout of 4 s" in result.reason


def test_kinematic_limit_and_perception_attribution():
    world, resolver, ex = make(recovery=RecoveryPolicy(max_retries=0))
    world.unreachable.add("plate")
    result = ex.run(parse_plan(PICK_PLACE))
    assert result.failure is FailureKind.KINEMATIC_LIMIT and result.failed_node == "tree.children[2]"

    world, resolver, ex = make()
    resolver.hidden.add("plate")
    result = ex.run(parse_plan(PICK_PLACE))
    assert result.failure is FailureKind.PERCEPTION
    assert "label 'plate' not resolved" in result.reason
    assert resolver.refreshes == 2  # tier 2 re-detected twice before failing closed


def test_late_binding_redetect_finds_the_moved_object():
    """The cube moves after perception ran; the stale grasp fails; tier 2 re-detects and the retry succeeds."""
    world, resolver, ex = make()
    ex.bus.subscribe(
        lambda e: e.node_path == "tree" and e.kind == "started" and world.move_object("cube", [0.6, -0.1, 0.02])
    )
    result = ex.run(parse_plan(PICK_PLACE))
    assert result.outcome == "success"
    first, *rest = [pos for label, pos in resolver.resolved if label == "cube"]
    assert first == pytest.approx((0.5, 0.0, 0.02)) and rest[-1] == pytest.approx((0.6, -0.1, 0.02))
    assert result.nodes["tree.children[1]"].recoveries[-1] == "tier2:retract+redetect+reapproach:move_to_keypoint"
    assert world.held["right"] is None and world.objects["cube"] == pytest.approx([0.5, 0.2, 0.06])


def test_late_binding_in_a_skill_resolves_at_retry_time():
    world, resolver, ex = make()
    ex.bus.subscribe(
        lambda e: e.node_path == "tree" and e.kind == "started" and world.move_object("cube", [0.6, -0.1, 0.02])
    )
    result = ex.run(parse_plan("task: t\ntree: {primitive: pick, params: {keypoint_label: cube}}"))
    assert result.outcome == "success" and world.held["right"] == "cube"
    # tier 1 perturbs in place (perception still stale, fails again); tier 2 re-detects and the pick succeeds
    assert result.nodes["tree"].recoveries == ["tier1:grasp_perturb", "tier2:retract+redetect"]


def test_fallback_tries_children_in_order():
    world, _, ex = make()
    world.unreachable.add("cube")
    plan = parse_plan("""
task: pick something
tree:
  type: fallback
  children:
    - primitive: pick
      params: {keypoint_label: cube}
    - primitive: pick
      params: {keypoint_label: plate}
""")
    result = ex.run(plan)
    assert result.outcome == "success"
    assert result.nodes["tree.children[0]"].status == "failed"
    assert result.nodes["tree.children[1]"].status == "succeeded"
    assert world.held["right"] == "plate"


def test_success_predicate_false_is_attributed_to_the_planner():
    _, _, ex = make(success_check=lambda: False)
    result = ex.run(parse_plan(PICK_PLACE))
    assert result.outcome == "failure" and result.failure is FailureKind.PLANNER


def test_unknown_arm_on_embodiment_fails_without_retry():
    _, _, ex = make()
    result = ex.run(parse_plan("task: t\ntree: {primitive: wait, arm: left}"))
    assert result.failure is FailureKind.PLANNER and "arm 'left' does not exist" in result.reason
    assert not [e for e in result.events if e.kind == "retrying"]


def test_tier_three_replans_once_when_enabled():
    world, _, _ = make()
    calls = []

    def replanner(req):
        calls.append(req.failure.node_path)
        return parse_plan("task: t\ntree: {primitive: pick, params: {keypoint_label: plate}}")

    resolver = KinematicResolver(world)
    world.unreachable.add("cube")
    ex = Executor(world, resolver, recovery=RecoveryPolicy(replan=True), replanner=replanner)
    result = ex.run(parse_plan("task: t\ntree: {primitive: pick, params: {keypoint_label: cube}}"))
    assert calls == ["tree"] and result.outcome == "success" and result.replans == 1
    assert ("tree", "retrying") in trail(result) and ("replan[1].tree", "succeeded") in trail(result)

    world2, _, ex2 = make(replanner=replanner)  # tier 3 is off by default
    world2.unreachable.add("cube")
    assert ex2.run(parse_plan("task: t\ntree: {primitive: pick, params: {keypoint_label: cube}}")).replans == 0


def test_async_stream_yields_the_same_events():
    world, resolver, _ = make()
    bus = EventBus("t2")
    ex = Executor(world, resolver, bus=bus)

    async def consume():
        task = asyncio.get_running_loop().run_in_executor(None, ex.run, parse_plan(PICK_PLACE))
        got = [e async for e in bus.stream()]
        return got, await task

    got, result = asyncio.run(consume())
    assert [(e.seq, e.kind) for e in got] == [(e.seq, e.kind) for e in result.events]
