"""Property: any tree generated from the registry round-trips parse -> serialise -> parse."""

import json

from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st

from spark_core.grammar import REGISTRY, ArmUse, SlotType, parse_plan, plan_to_dict, to_yaml

_label = st.text(st.characters(codec="utf-8", exclude_categories=("Cs", "Cc")), min_size=1, max_size=30).filter(
    lambda s: s.strip()
)


def _value(slot):
    t = slot.type
    if t is SlotType.LABEL:
        return _label
    if t is SlotType.ENUM:
        return st.sampled_from(slot.values)
    if t is SlotType.BOOL:
        return st.booleans()
    if t is SlotType.STRING:
        return st.text(max_size=20)
    lo, hi = slot.minimum, slot.maximum
    if t is SlotType.INTEGER:
        return st.integers(int(lo), int(hi))
    return st.floats(lo, hi, allow_nan=False, allow_infinity=False)


@st.composite
def primitive_node(draw, arm_scope=None):
    spec = draw(st.sampled_from([s for s in REGISTRY if not (arm_scope and s.uses_both_arms)]))
    params = {}
    for slot in spec.slots:
        if slot.required or draw(st.booleans()):
            params[slot.name] = draw(_value(slot))
    if spec.name == "handoff":
        params["to_arm"] = "right" if params["from_arm"] == "left" else "left"
    node = {"primitive": spec.name}
    if (
        spec.arm is ArmUse.REQUIRED
        and arm_scope is None
        or spec.arm is not ArmUse.NONE
        and arm_scope is None
        and draw(st.booleans())
    ):
        node["arm"] = draw(st.sampled_from(["left", "right"]))
    elif arm_scope is not None and spec.arm is not ArmUse.NONE and draw(st.booleans()):
        node["arm"] = arm_scope
    if params:
        node["params"] = params
    if draw(st.booleans()):  # the paper's leaf form: `type: <primitive>`, the arm inside params
        node = {"type": node.pop("primitive"), **node}
        if "arm" in node:
            node["params"] = {"arm": node.pop("arm"), **node.get("params", {})}
    return node


def tree(arm_scope=None, depth=0):
    leaf = primitive_node(arm_scope)
    if depth >= 3:
        return leaf
    kids = st.lists(st.deferred(lambda: tree(arm_scope, depth + 1)), min_size=1, max_size=4)
    composite = st.builds(lambda t, c: {"type": t, "children": c}, st.sampled_from(["sequence", "fallback"]), kids)
    options = [leaf, composite]
    if arm_scope is None:
        branches = st.tuples(tree("left", depth + 1), tree("right", depth + 1)).map(
            lambda lr: {
                "type": "parallel",
                "children": [
                    {"type": "sequence", "arm": "left", "children": [lr[0]]},
                    {"type": "sequence", "arm": "right", "children": [lr[1]]},
                ],
            }
        )
        options.append(branches)
    return st.one_of(options)


@settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(task=_label, root=tree())
@example(task="0", root={"primitive": "pick", "params": {"keypoint_label": "0\xa0"}})  # found by hypothesis
@example(task=" yes", root={"primitive": "pick", "params": {"keypoint_label": ":\xa0"}})
def test_generated_tree_round_trips(task, root):
    first = parse_plan(json.dumps({"task": task, "tree": root}))
    again = parse_plan(to_yaml(first))
    assert again == first
    assert parse_plan(json.dumps(plan_to_dict(again))) == first
    assert to_yaml(again) == to_yaml(first)
