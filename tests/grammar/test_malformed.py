"""Every error class and path shape of the type-checker: each malformed plan names the exact path and problem."""

import json

import pytest

from spark_core.grammar import PlanError, parse_plan


def seq(*children, **extra):
    return {"type": "sequence", "children": list(children), **extra}


def prim(name, arm=None, **params):
    node = {"primitive": name}
    if arm:
        node["arm"] = arm
    if params:
        node["params"] = params
    return node


def plan(tree, task="t"):
    return {"task": task, "tree": tree}


MOVE = prim("move_to_keypoint", keypoint_label="cup")
BR_L = seq(prim("pick_with_arm", keypoint_label="fork"), arm="left")
BR_R = seq(prim("pick_with_arm", keypoint_label="spoon"), arm="right")

CASES = [
    # (id, data, [(path, message substring), ...])
    ("top-not-mapping", ["a"], [("plan", "expected a mapping with 'task' and 'tree'")]),
    ("top-scalar", 42, [("plan", "got 42")]),
    ("missing-task", {"tree": MOVE}, [("task", "missing required key")]),
    ("missing-tree", {"task": "x"}, [("tree", "missing required key: the behavior tree")]),
    ("task-not-string", {"task": 3, "tree": MOVE}, [("task", "expected a non-empty string, got 3")]),
    ("task-empty", {"task": "  ", "tree": MOVE}, [("task", "expected a non-empty string")]),
    (
        "unknown-top-key",
        {"task": "x", "tree": MOVE, "tre": 1},
        [("tre", "unknown top-level key (did you mean 'tree'?)")],
    ),
    (
        "tree-not-mapping",
        plan("pick the cup"),
        [("tree", "expected a node (mapping with 'primitive' or 'type'), got \"pick the cup\"")],
    ),
    ("tree-list", plan([MOVE]), [("tree", "expected a node")]),
    ("node-no-kind", plan({"params": {}}), [("tree", "node needs 'primitive' or 'type'")]),
    (
        "node-both-kinds",
        plan({"type": "sequence", "primitive": "grasp"}),
        [("tree", "'type' (a composite or a primitive) or 'primitive', not both")],
    ),
    ("unknown-primitive", plan(prim("grap")), [("tree.primitive", "unknown primitive 'grap' (did you mean 'grasp'?)")]),
    ("unknown-primitive-no-hint", plan(prim("teleport")), [("tree.primitive", "unknown primitive 'teleport'")]),
    (
        "primitive-not-string",
        plan({"primitive": ["grasp"]}),
        [("tree.primitive", 'expected a primitive name, got ["grasp"]')],
    ),
    (
        "unknown-primitive-nested",
        plan(seq(MOVE, seq(prim("grasp"), prim("relase")))),
        [("tree.children[1].children[1].primitive", "(did you mean 'release'?)")],
    ),
    (
        "unknown-slot",
        plan(prim("grasp", forse=10)),
        [("tree.params.forse", "unknown slot (did you mean 'force'?); grasp takes force, target_width")],
    ),
    ("unknown-slot-no-params", plan(prim("release", width=0.08)), [("tree.params.width", "release takes no params")]),
    (
        "missing-required",
        plan(prim("move_to_keypoint", offset_z=0.1)),
        [("tree.params.keypoint_label", "missing required slot of move_to_keypoint")],
    ),
    (
        "missing-required-null",
        plan(prim("stack", keypoint_label="a", target_label=None)),
        [("tree.params.target_label", "missing required slot of stack")],
    ),
    (
        "missing-two-required",
        plan(prim("drag")),
        [("tree.params.keypoint_label", "missing required"), ("tree.params.target_label", "missing required")],
    ),
    (
        "wrong-type-string-for-number",
        plan(seq(MOVE, MOVE, prim("grasp", force="high"))),
        [("tree.children[2].params.force", 'expected number in [0, 140], got "high"')],
    ),
    (
        "wrong-type-bool-for-number",
        plan(prim("wait", duration=True)),
        [("tree.params.duration", "expected number in [0, 30], got true")],
    ),
    (
        "out-of-range-high",
        plan(prim("grasp", force=500)),
        [("tree.params.force", "expected number in [0, 140], got 500")],
    ),
    (
        "out-of-range-low",
        plan(prim("wait", duration=-1)),
        [("tree.params.duration", "expected number in [0, 30], got -1")],
    ),
    (
        "integer-slot-float",
        plan(prim("wipe", keypoint_label="table", n_strokes=2.5)),
        [("tree.params.n_strokes", "expected integer in [1, 20], got 2.5")],
    ),
    (
        "enum-invalid",
        plan(prim("push_object", keypoint_label="box", direction="north")),
        [("tree.params.direction", 'expected one of forward, backward, left, right, got "north"')],
    ),
    (
        "enum-wrong-type",
        plan(prim("grasp_se3", keypoint_label="mug", strategy=1)),
        [("tree.params.strategy", "expected one of top_down, side, axis_aligned, got 1")],
    ),
    (
        "label-empty",
        plan(prim("pick", keypoint_label="")),
        [("tree.params.keypoint_label", "expected non-empty object label")],
    ),
    ("label-number", plan(prim("pick", keypoint_label=7)), [("tree.params.keypoint_label", "got 7")]),
    (
        "label-too-long",
        plan(prim("pick", keypoint_label="x" * 300)),
        [("tree.params.keypoint_label", "at most 200 characters")],
    ),
    (
        "params-not-mapping",
        plan({"primitive": "grasp", "params": [50]}),
        [("tree.params", "expected a mapping of slot names to values, got [50]")],
    ),
    (
        "unknown-node-key",
        plan({"primitive": "grasp", "parameters": {}}),
        [("tree.parameters", "unknown key for a primitive node (did you mean 'params'?)")],
    ),
    (
        "unknown-composite-type",
        plan({"type": "sequense", "children": [MOVE]}),
        [("tree.type", "expected one of sequence, parallel, fallback, got \"sequense\" (did you mean 'sequence'?)")],
    ),
    ("composite-no-children", plan({"type": "sequence"}), [("tree.children", "missing required key")]),
    ("composite-empty-children", plan(seq()), [("tree.children", "a sequence needs at least one child")]),
    (
        "composite-children-not-list",
        plan({"type": "fallback", "children": MOVE}),
        [("tree.children", "expected a list of nodes")],
    ),
    (
        "composite-unknown-key",
        plan({"type": "sequence", "children": [MOVE], "name": "x"}),
        [("tree.name", "unknown key for a composite node")],
    ),
    (
        "child-not-mapping",
        plan(seq(MOVE, "grasp")),
        [("tree.children[1]", "expected a node (mapping with 'primitive' or 'type'), got \"grasp\"")],
    ),
    (
        "arm-invalid-value",
        plan(prim("grasp", arm="middle")),
        [("tree.arm", 'expected one of left, right, got "middle"')],
    ),
    (
        "arm-on-armless-primitive",
        plan(prim("redetect", arm="left")),
        [("tree.arm", "redetect does not take an arm tag")],
    ),
    (
        "arm-required-missing",
        plan(prim("pick_with_arm", keypoint_label="fork")),
        [("tree.arm", "pick_with_arm needs an arm tag")],
    ),
    (
        "parallel-branch-no-arm",
        plan({"type": "parallel", "children": [BR_L, seq(prim("wait"))]}),
        [("tree.children[1].arm", "each parallel branch needs an arm tag")],
    ),
    (
        "parallel-same-arm",
        plan({"type": "parallel", "children": [BR_L, seq(prim("wait"), arm="left")]}),
        [("tree.children[1].arm", "arm 'left' already runs branch children[0]")],
    ),
    (
        "parallel-branch-mixed-arms",
        plan({"type": "parallel", "children": [seq(prim("wait", arm="left"), prim("wait", arm="right")), BR_R]}),
        [("tree.children[0]", "a parallel branch must use one arm, this one uses left, right")],
    ),
    (
        "arm-conflict-in-branch",
        plan({"type": "parallel", "children": [seq(prim("grasp", arm="right"), arm="left"), BR_R]}),
        [("tree.children[0].children[0].arm", "arm 'right' inside a branch that belongs to arm 'left'")],
    ),
    (
        "both-arms-inside-branch",
        plan({"type": "parallel", "children": [seq(prim("bimanual_lift", keypoint_label="pot"), arm="left"), BR_R]}),
        [("tree.children[0].children[0]", "bimanual_lift drives both arms and cannot run inside arm 'left'")],
    ),
    (
        "handoff-same-arm",
        plan(prim("handoff", keypoint_label="hammer", from_arm="left", to_arm="left")),
        [("tree.params.to_arm", "two different arms")],
    ),
    (
        "deep-path",
        plan(
            seq(
                MOVE,
                {
                    "type": "fallback",
                    "children": [seq(MOVE, prim("push_object", keypoint_label="b", direction="left", distance="far"))],
                },
            )
        ),
        [("tree.children[1].children[0].children[1].params.distance", 'expected number in [0, 0.5], got "far"')],
    ),
]


@pytest.mark.parametrize("data,expected", [c[1:] for c in CASES], ids=[c[0] for c in CASES])
def test_malformed_plan_names_path_and_problem(data, expected):
    with pytest.raises(PlanError) as info:
        parse_plan(json.dumps(data))
    got = [(i.path, i.message) for i in info.value.issues]
    for path, fragment in expected:
        assert any(p == path and fragment in m for p, m in got), f"expected {path}: ...{fragment}... in {got}"


def test_case_count_covers_the_issue_floor():
    assert len(CASES) >= 40


def test_all_errors_are_reported_not_only_the_first():
    data = plan(seq(prim("grasp", force="high"), prim("grap"), prim("wait", duration=99), prim("pick")))
    with pytest.raises(PlanError) as info:
        parse_plan(json.dumps(data))
    paths = [i.path for i in info.value.issues]
    assert paths == [
        "tree.children[0].params.force",
        "tree.children[1].primitive",
        "tree.children[2].params.duration",
        "tree.children[3].params.keypoint_label",
    ]
    assert str(info.value).splitlines()[0] == 'tree.children[0].params.force: expected number in [0, 140], got "high"'


def test_yaml_syntax_error_names_line():
    with pytest.raises(PlanError) as info:
        parse_plan("task: x\ntree:\n  type: sequence\n  children: [a, b\n")
    (issue,) = info.value.issues
    assert issue.path == "text" and "line" in issue.message and "invalid YAML/JSON" in issue.message


def test_empty_text():
    with pytest.raises(PlanError, match="plan text is empty"):
        parse_plan("   \n")
