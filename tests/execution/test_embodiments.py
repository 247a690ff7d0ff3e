"""The same grammar on three robot set-ups: UR10 with its own gripper, and the two-Panda cell where arm-tagged
branches run concurrently, a hand-over never leaves the object unsupported, and arms are kept apart."""

import numpy as np
import pytest

from spark_core.control.ur10 import STROKE_M, ur10
from spark_core.execution import Executor, FailureKind
from spark_core.execution.primitives import PrimitiveLibrary
from spark_core.grammar import parse_plan
from spark_core.perception.privileged import PrivilegedResolver
from spark_core.sim.embodiments import EMBODIMENTS
from spark_core.sim.tasks import BIMANUAL, BUILTIN, TASKS
from spark_core.trial import TrialConfig, run_trial


def _run(task: str, seed: int = 0, embodiment: str | None = None, plan: str | None = None, monitor=None):
    spec = TASKS[task]
    world = spec.make_world(seed, embodiment)
    resolver = PrivilegedResolver(world)
    if monitor is not None:
        world.monitors.append(monitor)
    ex = Executor(PrimitiveLibrary(world, resolver, seed=seed), resolver)
    result = ex.run(parse_plan(plan or spec.reference_plan_text()))
    world.settle(0.3)
    return world, result


def test_ur10_model_matches_between_physics_and_ik():
    world = BUILTIN["lift_block"].make_world(0, "ur10")
    try:
        kin = world.kinematics["right"]
        assert kin.nq == 6 and world.gripper_width_m("right") == pytest.approx(STROKE_M, abs=1e-3)
        for q in (ur10().home_q_rad, ur10().home_q_rad + 0.3):
            world.data.qpos[world._qadr["right"]] = q
            import mujoco

            mujoco.mj_forward(world.model, world.data)
            np.testing.assert_allclose(world.tcp_pose("right").position_m, kin.fk(q).position_m, atol=1e-6)
    finally:
        world.close()


@pytest.mark.parametrize("task", ["lift_block", "stack_two", "turn_on_stove", "open_drawer"])
def test_the_same_plan_text_runs_on_panda_and_ur10(task):
    text = BUILTIN[task].reference_plan_text()
    for embodiment in ("panda", "ur10"):
        world, result = _run(task, 0, embodiment, plan=text)
        ok = BUILTIN[task].success(world)
        world.close()
        assert result.outcome == "success" and ok, (embodiment, result.reason)


def test_parallel_arm_branches_overlap_in_time():
    world, result = _run("sort_bimanual")
    try:
        assert result.outcome == "success" and BIMANUAL["sort_bimanual"].success(world)
        spans = {}
        for ev in result.events:
            if (
                ev.kind in ("started", "succeeded")
                and ev.detail.get("primitive", "x")
                and ev.node_path.count("children") == 3
            ):
                spans.setdefault(ev.node_path, {})[ev.kind] = ev.t
        left = [v for p, v in spans.items() if p.startswith("tree.children[0].children[0]")]
        right = [v for p, v in spans.items() if p.startswith("tree.children[0].children[1]")]
        l0, l1 = min(v["started"] for v in left), max(v["succeeded"] for v in left)
        r0, r1 = min(v["started"] for v in right), max(v["succeeded"] for v in right)
        overlap = min(l1, r1) - max(l0, r0)
        assert overlap > 0.5 * min(l1 - l0, r1 - r0)  # both arms' picks and placements run at the same time
        arms = {ev.detail.get("arm") for ev in result.events if ev.kind == "started" and "primitive" in ev.detail}
        assert arms == {"left", "right"}
    finally:
        world.close()


def test_handoff_never_leaves_the_object_unsupported():
    unsupported = []

    def monitor(w):
        bar = w.body_id("red bar")
        held = any(bar in w.pinched_bodies(a) for a in w.arms)
        lo, _ = w.body_aabb("red bar")
        if not held and lo[2] > 0.005:  # neither hand holds it and it is off the table: falling
            unsupported.append(round(w.sim_time_s, 2))

    world, result = _run("handover_bar", monitor=monitor)
    try:
        assert result.outcome == "success" and BIMANUAL["handover_bar"].success(world), result.reason
        assert not unsupported, f"unsupported at t = {unsupported[:5]} s"
        bar = world.body_id("red bar")
        assert bar in world.pinched_bodies("left") and bar not in world.pinched_bodies("right")
    finally:
        world.close()


COLLIDING = """
task: both arms reach for the same block at once
tree:
  type: parallel
  children:
    - primitive: move_to_keypoint_arm
      arm: left
      params: {keypoint_label: red block, offset_z: 0.05}
    - primitive: move_to_keypoint_arm
      arm: right
      params: {keypoint_label: red block, offset_z: 0.05}
"""


def test_a_colliding_plan_fails_cleanly_without_the_arms_touching():
    touches = []

    def monitor(w):
        m, d = w.model, w.data
        for i in range(d.ncon):
            n1 = m.body(m.geom_bodyid[d.contact[i].geom1]).name
            n2 = m.body(m.geom_bodyid[d.contact[i].geom2]).name
            if {n1.split("/")[0], n2.split("/")[0]} == {"left", "right"}:
                touches.append((n1, n2))

    world, result = _run("lift_block", embodiment="bimanual", plan=COLLIDING, monitor=monitor)
    try:
        assert result.outcome == "failure" and result.failure is FailureKind.COLLISION
        assert "arm's hand" in result.reason and "refused before moving" in result.reason
        assert not touches
    finally:
        world.close()


def test_two_arm_skills_refuse_a_one_arm_robot():
    world, result = _run(
        "lift_block", plan="task: t\ntree: {primitive: bimanual_lift, params: {keypoint_label: red block}}"
    )
    world.close()
    assert result.outcome == "failure" and "two arms" in result.reason


def test_embodiment_registry_and_task_fit():
    from spark_core.catalog import EMBODIMENTS as CATALOGUED

    assert set(EMBODIMENTS) == {"panda", "ur10", "bimanual"} == set(CATALOGUED)
    with pytest.raises(ValueError, match="needs one of the embodiments bimanual"):
        BIMANUAL["lift_tray"].make_world(0, "panda")


@pytest.mark.parametrize("task", list(BIMANUAL))
def test_bimanual_tasks_succeed_with_reference_plans(task):
    out = run_trial(TrialConfig(task, segmenter="privileged-keypoints", seed=1))
    assert out.success, (out.failure, out.reason)
