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
