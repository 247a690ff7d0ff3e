"""Primitives on the MuJoCo world: post-conditions catch their own failures; late binding re-resolves."""

import numpy as np
import pytest

from spark_core.execution import Executor, FailureKind, RecoveryPolicy
from spark_core.execution.primitives import IMPLEMENTATIONS, PrimitiveLibrary
from spark_core.grammar import REGISTRY, PrimitiveCall, parse_plan
from spark_core.perception.privileged import PrivilegedResolver
from spark_core.sim.tasks import BUILTIN

EXECUTOR_HANDLED = {"redetect", "replan", "sync_barrier"}


def setup(task="stack_two", seed=0):
    world = BUILTIN[task].make_world(seed)
    resolver = PrivilegedResolver(world)
    return world, resolver, PrimitiveLibrary(world, resolver, seed=seed)


def run(plan_text, task="stack_two", seed=0, recovery=RecoveryPolicy(), hook=None):
    world, resolver, lib = setup(task, seed)
    ex = Executor(lib, resolver, recovery=recovery)
    if hook:
        ex.bus.subscribe(lambda e: hook(e, world))
    return world, resolver, ex.run(parse_plan(plan_text))


def test_every_single_arm_primitive_is_implemented():
    single_arm = {s.name for s in REGISTRY if not s.uses_both_arms and s.name not in EXECUTOR_HANDLED}
    missing = single_arm - set(IMPLEMENTATIONS)
    assert not missing, f"no implementation for {sorted(missing)}"
    two_arm = {s.name for s in REGISTRY if s.uses_both_arms}
    assert two_arm <= set(IMPLEMENTATIONS), f"no implementation for {sorted(two_arm - set(IMPLEMENTATIONS))}"


def test_grasp_on_empty_air_fails_its_postcondition():
    world, _, result = run(
        """
task: grasp nothing
tree:
  type: sequence
  children:
    - primitive: move_relative
      params: {dz: -0.1}
    - primitive: grasp
""",
        recovery=RecoveryPolicy(max_retries=0),
    )
    assert result.failure is FailureKind.CONTROL and result.failed_node == "tree.children[1]"
    assert "gripper closed on nothing" in result.reason


def test_blocked_drawer_fails_open_drawer():
    world, resolver, lib = setup("open_drawer")
    slide = world.model.joint("cabinet/drawer_slide")
    world.model.jnt_range[slide.id] = [0.0, 0.005]  # a jammed drawer: it cannot travel
    result = Executor(lib, resolver, recovery=RecoveryPolicy(max_retries=0)).run(
        parse_plan("task: t\ntree: {primitive: open_drawer, params: {keypoint_label: cabinet drawer handle}}")
    )
    assert result.outcome == "failure" and result.failure is FailureKind.CONTROL
    assert "blocked" in result.reason or "slipped" in result.reason
    assert world.joint_value("cabinet/drawer_slide") < 0.01


def test_place_onto_a_target_that_moved_fails():
    """The plate moves after its keypoint was resolved: the descent feels no support where it expected it."""
    world, resolver, lib = setup("block_on_plate")
    out = lib.perform(
        PrimitiveCall("pick", {"keypoint_label": "red block"}),
        {"red block": resolver.resolve("red block")},
        "right",
        10,
    )
    assert out.ok, out.reason
    stale = resolver.resolve("plate")
    world.set_body_position("plate", [0.62, -0.3, 0.0])
    out = lib.perform(PrimitiveCall("place", {"target_label": "plate"}), {"plate": stale}, "right", 10)
    assert not out.ok and out.failure is FailureKind.PERCEPTION
    assert "it moved or is not there" in out.reason
    assert lib.memory["right"].held_label == "red block"  # still held: a retry can re-detect and place it


def test_moving_an_object_mid_plan_is_handled_by_late_binding():
    """The blue block is moved after the red one is picked; the place resolves its label when it runs."""
    moved = {}

    def hook(ev, world):
        if ev.node_path == "tree.children[0]" and ev.kind == "succeeded":
            world.set_body_position("blue block", [0.45, 0.25, 0.0])
            moved["to"] = world.body_position("blue block")

    world, resolver, result = run(
        """
task: stack
tree:
  type: sequence
  children:
    - primitive: pick
      params: {keypoint_label: red block}
    - primitive: place
      params: {target_label: blue block}
""",
        hook=hook,
    )
    assert result.outcome == "success", result.reason
    red, blue = world.body_position("red block"), world.body_position("blue block")
    assert np.linalg.norm(red[:2] - blue[:2]) < 0.02 and red[2] > blue[2] + 0.03
    assert np.linalg.norm(blue[:2] - moved["to"][:2]) < 0.01


def test_retry_after_redetect_reaches_the_moved_object():
    """A grasp that closes on air because the block moved is retried after re-detection and succeeds."""

    def hook(ev, world):
        if ev.node_path == "tree.children[1]" and ev.kind == "succeeded":  # hand is at the block: move it
            world.set_body_position("red block", world.body_position("red block") + [0.0, 0.08, 0.0])

    world, resolver, result = run(
        """
task: pick
tree:
  type: sequence
  children:
    - primitive: move_to_keypoint
      params: {keypoint_label: red block, offset_z: 0.10}
    - primitive: move_to_keypoint
      params: {keypoint_label: red block, offset_z: 0.0}
    - primitive: grasp
    - primitive: move_relative
      params: {dz: 0.1}
""",
        hook=hook,
    )
    assert result.outcome == "success", result.reason
    grasp = result.nodes["tree.children[2]"]
    assert grasp.retries >= 1 and grasp.recoveries[-1].startswith("tier2:retract+redetect+reapproach")
    assert world.body_position("red block")[2] > 0.05  # lifted
    assert resolver.refreshes >= 1


def test_move_to_unreachable_keypoint_is_a_kinematic_failure():
    world, resolver, lib = setup()
    far = resolver.resolve("red block")
    far = type(far)(far.label, np.array([1.6, 0.0, 0.02]), far.extent_m, far.yaw_rad, far.source)
    out = lib.perform(
        PrimitiveCall("move_to_keypoint", {"keypoint_label": "red block"}), {"red block": far}, "right", 4
    )
    assert not out.ok and out.failure is FailureKind.KINEMATIC_LIMIT and "1.6" in out.reason


SAMPLE = ["lift_block", "stack_two", "open_drawer", "turn_on_stove"]


@pytest.mark.parametrize(
    "task",
    [t for t in BUILTIN if t in SAMPLE] + [pytest.param(t, marks=pytest.mark.slow) for t in BUILTIN if t not in SAMPLE],
)
def test_reference_plan_solves_the_task(task):
    from spark_core.trial import TrialConfig, run_trial

    out = run_trial(TrialConfig(task, segmenter="privileged-keypoints", seed=0))
    assert out.success, f"{out.verdict}: {out.failed_node} {out.reason}"
    assert out.protocol["segmenter"] == "privileged-keypoints" and out.protocol["privileged"] is True


@pytest.mark.parametrize("task", ["stack_two", pytest.param("block_in_drawer", marks=pytest.mark.slow)])
def test_reference_plan_through_cameras_and_the_sim_segmenter(task):
    """The full perception path: cameras -> sim masks -> depth lifting -> keypoints, re-resolved every node."""
    from spark_core.trial import TrialConfig, run_trial

    out = run_trial(TrialConfig(task, segmenter="sim", seed=1))
    assert out.success, f"{out.verdict}: {out.failed_node} {out.reason}"
    assert out.protocol["segmenter"] == "sim" and out.protocol["privileged"] is True
    assert out.protocol["cameras"] == "scene default" and out.protocol["adaptive_prompts"] is True


def test_a_seen_object_is_grasped_across_its_short_side_however_it_is_turned():
    """Camera keypoints carry the seen top face's length along the yaw axis: a bar turned 57 degrees has a nearly
    square world box, which must not decide the side the fingers close across."""
    from spark_core.control.pose import wrap_grasp_yaw
    from spark_core.execution.primitives.base import ArmMemory, Ctx
    from spark_core.perception import Keypoint

    bar = Keypoint(
        "bar", np.zeros(3), np.array([0.07, 0.08, 0.02]), yaw_rad=-1.0, detail={"principal_extent_m": [0.11, 0.02]}
    )  # yaw runs along the long side (lifting)
    ctx = Ctx(world=None, arm="right", motion=None, args={}, keypoints={}, memory=ArmMemory())
    assert ctx.grasp_yaw(bar) == pytest.approx(wrap_grasp_yaw(-1.0))  # hand x along the bar: fingers across it
