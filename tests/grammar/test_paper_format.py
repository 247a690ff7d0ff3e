"""The paper's plan format: a leaf is `type: <primitive>` with `params:`, the arm inside `params` or on the node;
the older `primitive:` leaf still parses to the same Plan; the project writes the paper's form."""

import json
from pathlib import Path

import jsonschema
import pytest

from spark_core.grammar import PlanError, parse_plan, plan_json_schema, plan_to_dict, to_yaml
from spark_core.planning.prompt import system_prompt

ROOT = Path(__file__).resolve().parents[2]

PAPER = """
task: sort the fork and the spoon
tree:
  type: sequence
  children:
    - type: move_to_keypoint
      params: {keypoint_label: fork, offset_z: 0.1}
    - type: grasp
      params: {force: 30}
    - type: parallel
      children:
        - type: sequence
          children:
            - type: pick_with_arm
              params: {arm: left, keypoint_label: fork, target_width: 0.02, force: 20, prefer_angled: true}
            - type: place_with_arm
              params: {arm: left, tilt_angle: 0.3}
        - type: sequence
          arm: right
          children:
            - type: pick_with_arm
              params: {keypoint_label: spoon}
            - type: place_with_arm
              params: {target_label: right tray}
    - type: go_home
"""

OLD = """
task: sort the fork and the spoon
tree:
  type: sequence
  children:
    - primitive: move_to_keypoint
      params: {keypoint_label: fork, offset_z: 0.1}
    - primitive: grasp
      params: {force: 30}
    - type: parallel
      children:
        - type: sequence
          children:
            - primitive: pick_with_arm
              arm: left
              params: {keypoint_label: fork, target_width: 0.02, force: 20, prefer_angled: true}
            - primitive: place_with_arm
              arm: left
              params: {tilt_angle: 0.3}
        - type: sequence
          arm: right
          children:
            - primitive: pick_with_arm
              params: {keypoint_label: spoon}
            - primitive: place_with_arm
              params: {target_label: right tray}
    - primitive: go_home
"""


def issues(text):
    with pytest.raises(PlanError) as info:
        parse_plan(text)
    return [(i.path, i.message) for i in info.value.issues]


def test_the_papers_leaf_form_parses_to_the_same_plan_as_the_old_form():
    paper, old = parse_plan(PAPER), parse_plan(OLD)
    assert paper == old
    left = paper.node_at("tree.children[2].children[0].children[0]")
    assert left.primitive == "pick_with_arm" and left.arm == "left" and "arm" not in left.params
    assert left.params == {"keypoint_label": "fork", "target_width": 0.02, "force": 20.0, "prefer_angled": True}
    assert {arm for _, _, arm in paper.primitives() if arm} == {"left", "right"}


@pytest.mark.parametrize(
    "leaf",
    [
        "{type: grasp, params: {arm: left, force: 30}}",
        "{type: grasp, arm: left, params: {force: 30}}",
        "{type: grasp, arm: left, params: {arm: left, force: 30}}",
        "{primitive: grasp, arm: left, params: {force: 30}}",
        "{primitive: grasp, params: {arm: left, force: 30}}",
    ],
)
def test_arm_inside_params_or_on_the_node_is_the_same_call(leaf):
    plan = parse_plan(f"task: t\ntree: {leaf}")
    assert plan.tree.arm == "left" and plan.tree.params == {"force": 30.0}


def test_a_type_that_names_a_composite_is_a_composite_and_a_primitive_a_leaf():
    plan = parse_plan("task: t\ntree: {type: fallback, children: [{type: wait}, {type: release}]}")
    assert plan.tree.type.value == "fallback" and [c.primitive for c in plan.tree.children] == ["wait", "release"]


def test_to_yaml_writes_the_papers_form_and_round_trips():
    plan = parse_plan(OLD)
    text = to_yaml(plan)
    assert "primitive:" not in text and "\n  - type: go_home\n" in text
    assert "      - type: pick_with_arm\n        params:\n          arm: left\n          keypoint_label: fork\n" in text
    assert parse_plan(text) == plan and to_yaml(parse_plan(text)) == text
    tree = plan_to_dict(plan)["tree"]
    assert tree["children"][1] == {"type": "grasp", "params": {"force": 30.0}}
    right = tree["children"][2]["children"][1]
    assert right["arm"] == "right" and right["children"][0] == {
        "type": "pick_with_arm",
        "params": {"keypoint_label": "spoon"},
    }
    compact = to_yaml(plan, compact=True)
    assert "params: {arm: left, tilt_angle: 0.3}" in compact and parse_plan(compact) == plan
    # the older form, for readers that tell leaves by `primitive` (the console's stored tree)
    old = plan_to_dict(plan, form="primitive")
    assert old["tree"]["children"][0]["primitive"] == "move_to_keypoint"
    assert parse_plan(json.dumps(old)) == plan


@pytest.mark.parametrize(
    "tree,expected",
    [
        (
            "{type: sequence, children: [{type: wait}, {type: wait}, {type: grasp, params: {force: high}}]}",
            ("tree.children[2].params.force", 'expected number in [0, 140], got "high"'),
        ),
        ("{type: grap}", ("tree.type", "unknown primitive 'grap' (did you mean 'grasp'?)")),
        ("{type: sequense, children: [{type: wait}]}", ("tree.type", "expected one of sequence, parallel, fallback")),
        (
            "{type: grasp, parameters: {}}",
            ("tree.parameters", "unknown key for a primitive node (did you mean 'params'?)"),
        ),
        ("{type: grasp, children: []}", ("tree.children", "unknown key for a primitive node")),
        ("{type: pick, params: {lift_height: 0.1}}", ("tree.params.keypoint_label", "missing required slot of pick")),
        (
            "{type: pick_with_arm, params: {keypoint_label: fork}}",
            ("tree.params.arm", "pick_with_arm needs an arm tag"),
        ),
        ("{type: grasp, params: {arm: middle}}", ("tree.params.arm", 'expected one of left, right, got "middle"')),
        ("{type: redetect, params: {arm: left}}", ("tree.params.arm", "redetect does not take an arm tag")),
        ("{type: grasp, arm: left, params: {arm: right}}", ("tree.params.arm", "disagrees with the node's arm 'left'")),
        (
            "{type: sequence, arm: left, children: [{type: grasp, params: {arm: right}}]}",
            ("tree.children[0].params.arm", "arm 'right' inside a branch that belongs to arm 'left'"),
        ),
        (
            "{type: parallel, children: [{type: wait, params: {arm: left}}, {type: wait, params: {arm: left}}]}",
            ("tree.children[1].arm", "arm 'left' already runs branch children[0]"),
        ),
        ("{type: [grasp]}", ("tree.type", 'expected one of sequence, parallel, fallback, got ["grasp"]')),
    ],
)
def test_errors_in_the_papers_form_name_the_exact_path(tree, expected):
    got = issues(f"task: t\ntree: {tree}")
    path, fragment = expected
    assert any(p == path and fragment in m for p, m in got), got


@pytest.mark.parametrize(
    "params,expected",
    [
        ("{arm: left, keypoint_label: fork, target_width: 0.2}", ("target_width", "expected number in [0, 0.085]")),
        ("{arm: left, keypoint_label: fork, force: 200}", ("force", "expected number in [0, 140], got 200")),
        ("{arm: left, keypoint_label: fork, force: strong}", ("force", 'got "strong"')),
        ("{arm: left, keypoint_label: fork, prefer_angled: yes please}", ("prefer_angled", "expected true or false")),
        ("{arm: left, keypoint_label: fork, prefer_angled: 1}", ("prefer_angled", "expected true or false, got 1")),
    ],
)
def test_pick_with_arm_slots_are_typed(params, expected):
    slot, fragment = expected
    got = issues(f"task: t\ntree: {{type: pick_with_arm, params: {params}}}")
    assert any(p == f"tree.params.{slot}" and fragment in m for p, m in got), got


@pytest.mark.parametrize(
    "params,expected",
    [
        ("{arm: left, tilt_angle: 1.5}", ("tilt_angle", "expected number in [-1, 1], got 1.5")),
        ("{arm: left, tilt_angle: steep}", ("tilt_angle", 'got "steep"')),
        ("{arm: left, target_label: ''}", ("target_label", "expected non-empty object label")),
        ("{arm: left, container_label: tray}", ("container_label", "place_with_arm takes target_label, tilt_angle")),
    ],
)
def test_place_with_arm_slots_are_typed(params, expected):
    slot, fragment = expected
    got = issues(f"task: t\ntree: {{type: place_with_arm, params: {params}}}")
    assert any(p == f"tree.params.{slot}" and fragment in m for p, m in got), got


def test_place_with_arm_needs_no_target_label():
    here = parse_plan("task: t\ntree: {type: place_with_arm, params: {arm: right}}")
    assert here.tree.args == {"tilt_angle": 0.0} and here.labels() == []
    there = parse_plan("task: t\ntree: {type: place_with_arm, params: {arm: right, target_label: tray}}")
    assert there.labels() == ["tray"]
    pick = parse_plan("task: t\ntree: {type: pick_with_arm, params: {arm: right, keypoint_label: fork}}")
    assert pick.tree.args == {"keypoint_label": "fork", "lift_height": 0.1, "force": 50.0, "prefer_angled": False}


def test_the_json_schema_and_the_prompt_ask_for_the_papers_form():
    validator = jsonschema.Draft202012Validator(plan_json_schema())
    plan = parse_plan(PAPER)
    assert validator.is_valid(plan_to_dict(plan))
    assert not validator.is_valid(plan_to_dict(plan, form="primitive"))
    assert not validator.is_valid({"task": "t", "tree": {"type": "redetect", "params": {"arm": "left"}}})
    assert not validator.is_valid({"task": "t", "tree": {"type": "grasp", "params": {"arm": "middle"}}})
    assert validator.is_valid({"task": "t", "tree": {"type": "place_with_arm", "params": {"arm": "left"}}})
    prompt = system_prompt()
    assert '{"type": <primitive name>, "params": {"arm"?: "left"|"right", <slot>: <value>}}' in prompt
    assert '"primitive":' not in prompt
    assert "pick_with_arm{keypoint_label*, lift_height=0.1, target_width, force=50.0, prefer_angled=False}" in prompt


PLAN_FILES = sorted((ROOT / "examples/plans").glob("*.yaml")) + sorted(
    (ROOT / "spark_core/sim/tasks/reference").glob("*.yaml")
)


@pytest.mark.parametrize("path", PLAN_FILES, ids=lambda p: f"{p.parent.name}/{p.name}")
def test_checked_in_plans_are_in_the_canonical_form(path):
    text = path.read_text()
    header = "".join(line + "\n" for line in text.splitlines() if line.startswith("#"))
    assert "primitive:" not in text
    assert text == header + to_yaml(parse_plan(text), compact=True), (
        f"{path} is not canonical: run scripts/canonical_plans.py"
    )
