"""The rules planner: parsing, grounding against what perception saw, composition, and clear refusals."""

import numpy as np
import pytest

from spark_core.grammar import plan_to_dict
from spark_core.perception import Keypoint
from spark_core.planning import PlanRequest, SceneView
from spark_core.planning.observe import phrases_for
from spark_core.planning.rules import ParseError, RulesPlanner, parse_instruction


def kp(label, xyz, size=(0.04, 0.04, 0.04)):
    return Keypoint(label, np.array(xyz, float), np.array(size, float))


def scene(**objects):
    return SceneView(
        {
            k.replace("_", " "): kp(k, *v) if isinstance(v, tuple) and isinstance(v[0], tuple) else kp(k, v)
            for k, v in objects.items()
        }
    )


def prims(result):
    return [(c["type"], c.get("params", {})) for c in plan_to_dict(result.plan)["tree"]["children"]]


@pytest.mark.parametrize(
    "text,expected",
    [
        ("pick up the red block", [("pick", "red block", None, None)]),
        ("pick the red block up", [("pick", "red block", None, None)]),
        ("Could you please drop the crimson cube into the basket?", [("put", "crimson cube", "in", "basket")]),
        ("set the cup on top of the plate", [("put", "cup", "on", "plate")]),
        (
            "stack the green block on the blue block, then the red block on the green block",
            [("stack", "green block", "on", "blue block"), ("stack", "red block", "on", "green block")],
        ),
        ("open the drawer of the cabinet", [("open", "cabinet drawer", None, None)]),
        (
            "open the drawer and then drop the red block into it",
            [("open", "drawer", None, None), ("put", "red block", "in", "drawer")],  # "it": what was opened
        ),
        (
            "put the red block in the green tray and the blue block in the yellow tray",
            [("put", "red block", "in", "green tray"), ("put", "blue block", "in", "yellow tray")],
        ),
        ("turn the stove on", [("turn_on", "stove", None, None)]),
    ],
)
def test_parse(text, expected):
    got = [(c.action, c.obj, c.relation, c.target) for c in parse_instruction(text)]
    assert got == expected


def test_parse_tools_sources_directions_distances():
    (c,) = parse_instruction("use the sponge to scrub the plate")
    assert (c.action, c.target, c.tool) == ("scrub", "plate", "sponge")
    (c,) = parse_instruction("pour the beads from the mug into the bowl")
    assert (c.action, c.source, c.target) == ("pour", "mug", "bowl")
    (c,) = parse_instruction("push the red block 15 cm to the left")
    assert (c.direction, c.distance_m) == ("left", pytest.approx(0.15))


def test_unknown_verb_names_what_it_understands():
    with pytest.raises(ParseError, match="no action I know in 'fly to the moon'; I understand verbs such as"):
        parse_instruction("fly to the moon")


def test_phrases_include_the_parts_actions_need():
    assert phrases_for("open the drawer and put the red block inside it") == ["drawer", "drawer handle", "red block"]
    assert phrases_for("turn on the stove") == ["stove", "stove knob"]


def test_composes_pick_and_place():
    view = scene(red_block=(0.5, 0.0, 0.02), plate=((0.5, 0.2, 0.008), (0.18, 0.18, 0.016)))
    res = RulesPlanner().plan(PlanRequest("put the red block on the plate", view))
    assert res.ok and prims(res) == [("pick", {"keypoint_label": "red block"}), ("place", {"target_label": "plate"})]
    assert res.detail["understood"] == ["put obj=red block relation=on target=plate"]
    assert res.text.startswith("task: put the red block on the plate")


def test_open_then_put_inside_it_opens_wider_and_targets_the_drawer():
    view = scene(drawer=(0.7, 0.2, 0.07), drawer_handle=(0.65, 0.2, 0.09), red_block=(0.4, -0.1, 0.02))
    res = RulesPlanner().plan(PlanRequest("open the drawer and put the red block inside it", view))
    assert prims(res) == [
        ("open_drawer", {"keypoint_label": "drawer handle", "distance": 0.18}),
        ("pick", {"keypoint_label": "red block"}),
        ("place_in", {"container_label": "drawer"}),
    ]


def test_push_into_a_region_measures_distance_from_the_scene():
    view = scene(red_block=(0.42, 0.0, 0.02), green_area=((0.6, 0.01, 0.0), (0.14, 0.14, 0.001)))
    res = RulesPlanner().plan(PlanRequest("push the red block into the green area", view))
    ((name, params),) = prims(res)
    assert (
        name == "push_object"
        and params["direction"] == "forward"
        and params["distance"] == pytest.approx(0.18, abs=1e-3)
    )
    bad = RulesPlanner().plan(PlanRequest("push the red block backward into the green area", view))
    assert not bad.ok and "not backward" in bad.error


@pytest.mark.parametrize(
    "instruction,view,fragment",
    [
        (
            "put the giraffe on the plate",
            {"plate": (0.5, 0, 0.01)},
            "could not find 'giraffe' in the scene: perception found nothing that matches it",
        ),
        ("put the red block", {"red block": (0.5, 0, 0.02)}, "which destination?"),
        ("scrub the plate", {"plate": (0.5, 0, 0.01)}, "scrub with what?"),
        ("push the red block", {"red block": (0.5, 0, 0.02)}, "push which way?"),
        ("open the box", {"box": (0.5, 0, 0.02)}, "perception found no handle on it"),
        ("turn on the stove", {"stove": (0.5, 0, 0.02)}, "did not find it with a knob"),
        ("sing a song", {}, "did not understand the instruction"),
    ],
)
def test_refusals_are_clear(instruction, view, fragment):
    sv = SceneView({k: kp(k, v) for k, v in view.items()})
    res = RulesPlanner().plan(PlanRequest(instruction, sv))
    assert not res.ok and res.plan is None and fragment in res.error


def test_plans_type_check_and_round_trip():
    from spark_core.grammar import parse_plan

    view = scene(mug=(0.45, -0.1, 0.045), bowl=(0.55, 0.15, 0.025))
    res = RulesPlanner().plan(PlanRequest("pour the mug into the bowl", view))
    assert [p for p, _ in prims(res)] == ["grasp_se3", "lift", "pour"]
    assert parse_plan(res.text) == res.plan


def test_rules_plan_executes_in_physics_through_perception():
    """perception (sim masks) -> rules plan -> execution on the MuJoCo world."""
    from spark_core.execution import Executor
    from spark_core.execution.primitives import PrimitiveLibrary
    from spark_core.perception.factory import make_resolver
    from spark_core.planning.observe import observe
    from spark_core.sim.tasks import BUILTIN

    task = BUILTIN["stack_two"]
    world = task.make_world(3)
    resolver = make_resolver(world, "sim", 3)
    instruction = "put the crimson cube on top of the navy cube"
    res = RulesPlanner().plan(PlanRequest(instruction, observe(instruction, resolver)))
    assert res.ok, res.error
    trial = Executor(PrimitiveLibrary(world, resolver, seed=3), resolver).run(res.plan)
    world.settle(0.5)
    assert trial.outcome == "success" and task.success(world)
    world.close()


def test_an_object_located_by_others_keeps_its_relation_in_the_phrase():
    got = [
        (c.action, c.obj, c.target)
        for c in parse_instruction(
            "pick the akita black bowl between the plate and the ramekin and place it on the plate"
        )
    ]
    bowl = "akita black bowl between plate and ramekin"
    assert got == [("pick", bowl, None), ("put", bowl, "plate")]  # "it" resolved to the picked bowl
    assert parse_instruction("pick the bowl next to the cookie box")[0].obj == "bowl next to cookie box"


def test_pick_then_place_it_picks_once():
    view = scene(bowl_next_to_plate=(0.5, 0.1, 0.03), plate=((0.6, 0.0, 0.008), (0.18, 0.18, 0.016)))
    res = RulesPlanner().plan(PlanRequest("pick the bowl next to the plate and place it on the plate", view))
    assert prims(res) == [("pick", {"keypoint_label": "bowl next to plate"}), ("place", {"target_label": "plate"})]


def test_put_inside_after_opening_targets_the_opened_drawer():
    view = scene(drawer=(0.7, 0.2, 0.07), drawer_handle=(0.65, 0.2, 0.09), bowl=(0.4, -0.1, 0.03))
    res = RulesPlanner().plan(PlanRequest("open the drawer and put the bowl inside", view))
    assert prims(res)[-1] == ("place_in", {"container_label": "drawer"})


def test_an_arm_with_a_mounted_pad_wipes_the_region_without_picking_a_tool():
    seen = scene(dirt=((0.5, 0.0, 0.001), (0.2, 0.1, 0.002)))
    req = PlanRequest("wipe the dirt off the table", seen, arms={"right": (0.0, 0.0)}, tools={"right": "wiping pad"})
    assert prims(RulesPlanner().plan(req)) == [("wipe_area", {"keypoint_label": "dirt"})]
    bare = RulesPlanner().plan(PlanRequest("wipe the dirt off the table", seen, arms={"right": (0.0, 0.0)}))
    assert bare.plan is None and "scrub with what" in bare.error  # fingers and no tool named: ask for one


def test_the_prompt_tells_the_planner_which_arm_carries_a_mounted_tool():
    from spark_core.planning.prompt import user_prompt

    text = user_prompt(PlanRequest("wipe the table", arms={"right": (0.0, 0.0)}, tools={"right": "wiping pad"}))
    assert "right (base at x=0.00 m, y=0.00 m; carries a mounted wiping pad and has no fingers)" in text
