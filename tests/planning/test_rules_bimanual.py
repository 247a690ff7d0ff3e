"""The rules planner shares independent carries between two arms (arm-tagged parallel branches), and the
plan it writes runs for real on the two-arm cell through cameras and the sim segmenter."""

import numpy as np

from spark_core.execution import Executor
from spark_core.execution.primitives import PrimitiveLibrary
from spark_core.grammar import Composite
from spark_core.perception import Keypoint
from spark_core.perception.factory import make_resolver
from spark_core.planning import PlanRequest, SceneView
from spark_core.planning.observe import arm_bases, observe
from spark_core.planning.rules import RulesPlanner
from spark_core.sim.tasks import BIMANUAL

SORT = "put the red block in the red tray and the blue block in the blue tray"


def _scene() -> SceneView:
    kp = lambda label, x, y: Keypoint(label, np.array([x, y, 0.02]), np.array([0.04, 0.04, 0.04]))
    return SceneView(
        {
            k.label: k
            for k in (
                kp("red block", 0.5, 0.15),
                kp("red tray", 0.6, 0.33),
                kp("blue block", 0.45, -0.15),
                kp("blue tray", 0.6, -0.33),
            )
        }
    )


def test_two_arms_get_one_carry_each_in_parallel():
    result = RulesPlanner().plan(PlanRequest(SORT, _scene(), arms={"left": (0.0, 0.3), "right": (0.0, -0.3)}))
    assert result.ok, result.error
    par = result.plan.tree.children[0]
    assert isinstance(par, Composite) and par.type.value == "parallel"
    branches = {b.arm: [(c.primitive, c.labels) for c in b.children] for b in par.children}
    assert branches == {
        "left": [("pick_with_arm", ["red block"]), ("place_in", ["red tray"])],
        "right": [("pick_with_arm", ["blue block"]), ("place_in", ["blue tray"])],
    }


def test_one_arm_keeps_a_plain_sequence():
    for arms in ({}, {"right": (0.0, 0.0)}):
        plan = RulesPlanner().plan(PlanRequest(SORT, _scene(), arms=arms)).plan
        assert [c.primitive for c in plan.tree.children] == ["pick", "place_in", "pick", "place_in"]


def test_rules_bimanual_plan_runs_on_the_two_arm_cell_with_perception():
    task = BIMANUAL["sort_bimanual"]
    world = task.make_world(2)
    try:
        resolver = make_resolver(world, "sim", 2)
        result = RulesPlanner().plan(
            PlanRequest(task.instruction, observe(task.instruction, resolver), arms=arm_bases(world))
        )
        assert result.ok and "arm: left" in result.text and "arm: right" in result.text
        trial = Executor(PrimitiveLibrary(world, resolver, seed=2), resolver).run(result.plan)
        world.settle(0.5)
        assert trial.outcome == "success" and task.success(world), trial.reason
    finally:
        world.close()


def test_a_shared_destination_between_the_arms_leaves_each_object_to_its_nearer_arm():
    kp = lambda label, x, y: Keypoint(label, np.array([x, y, 0.02]), np.array([0.04, 0.04, 0.04]))
    view = SceneView({k.label: k for k in (kp("spoon", 0.42, 0.18), kp("pen", 0.42, -0.18), kp("box", 0.6, 0.0))})
    text = "put the spoon and the pen in the box"
    result = RulesPlanner().plan(PlanRequest(text, view, arms={"left": (0.0, 0.3), "right": (0.0, -0.3)}))
    assert result.ok, result.error
    grasp, *puts = result.plan.tree.children
    assert isinstance(grasp, Composite) and grasp.type.value == "parallel"  # both grasp at once
    assert {b.arm: [(c.primitive, c.labels) for c in b.children] for b in grasp.children} == {
        "left": [("pick_with_arm", ["spoon"])],
        "right": [("pick_with_arm", ["pen"])],
    }
    # then one after the other into the one box, each arm standing back after its turn
    assert [(b.type.value, b.arm, [c.primitive for c in b.children]) for b in puts] == [
        ("sequence", "left", ["place_in", "go_home"]),
        ("sequence", "right", ["place_in", "go_home"]),
    ]
