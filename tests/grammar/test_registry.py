"""The registry holds the paper's grammar with its signatures, defaults, timeouts and tiers."""

import json
from pathlib import Path

import jsonschema
import pytest

from spark_core.grammar import REGISTRY, ArmUse, Tier, parse_plan, plan_json_schema, plan_to_dict
from spark_core.grammar.reference import markdown

ROOT = Path(__file__).resolve().parents[2]


def test_tiers_and_counts():
    assert [s.name for s in REGISTRY.by_tier(Tier.BASE)] == [
        "move_to_keypoint",
        "move_relative",
        "grasp",
        "release",
        "wait",
    ]
    assert len(REGISTRY) - 5 >= 30
    assert len(REGISTRY.by_tier(Tier.SKILL)) >= 24
    assert {s.name for s in REGISTRY.by_tier(Tier.RECOVERY)} == {"wiggle", "grasp_perturb", "redetect", "replan"}
    assert {s.name for s in REGISTRY.by_tier(Tier.BIMANUAL)} == {
        "pick_with_arm",
        "place_with_arm",
        "move_to_keypoint_arm",
        "handoff",
        "sync_barrier",
        "bimanual_lift",
    }


@pytest.mark.parametrize(
    "name,required,defaults",
    [
        ("move_to_keypoint", {"keypoint_label"}, {"offset_z": 0.10, "offset_x": 0.0, "offset_y": 0.0}),
        ("move_relative", set(), {"dz": 0.0}),
        ("grasp", set(), {"force": 50.0}),
        ("wait", set(), {"duration": 0.5}),
        ("grasp_se3", {"keypoint_label"}, {"strategy": "top_down"}),
        ("insert", {"keypoint_label"}, {}),
        ("push_object", {"keypoint_label", "direction"}, {"distance": 0.10}),
        ("open_drawer", {"keypoint_label"}, {}),
        ("pour", {"target_label"}, {"pour_angle": 1.57}),
        ("sweep", {"keypoint_label"}, {"distance": 0.15}),
        ("wipe", {"keypoint_label"}, {}),
        ("constrained_scrub", {"target_label"}, {"force_n": 8.0}),
        ("pull", {"keypoint_label"}, {"distance": 0.10}),
        ("drag", {"keypoint_label", "target_label"}, {}),
        ("stack", {"keypoint_label", "target_label"}, {}),
        ("screw", {"keypoint_label"}, {"angle": 90.0}),
    ],
)
def test_paper_signatures(name, required, defaults):
    spec = REGISTRY[name]
    assert {s.name for s in spec.slots if s.required} == required
    for k, v in defaults.items():
        assert spec.defaults()[k] == v
    assert "target_width" in {s.name for s in REGISTRY["grasp"].slots}
    assert {"n_cycles", "scrub_radius_m", "pattern"} <= {s.name for s in REGISTRY["constrained_scrub"].slots}


@pytest.mark.parametrize(
    "name,timeout",
    [
        ("move_to_keypoint", 4),
        ("move_relative", 2),
        ("grasp", 1),
        ("release", 1),
        ("insert", 6),
        ("push_object", 4),
        ("open_drawer", 5),
        ("wipe", 10),
    ],
)
def test_paper_timeouts(name, timeout):
    assert REGISTRY[name].timeout_s == timeout


def test_every_spec_is_complete():
    for spec in REGISTRY:
        assert spec.description and spec.postcondition and spec.timeout_s > 0
        if spec.perturbation:
            assert spec.perturbation in ("wiggle", "grasp_perturb")
        for slot in spec.slots:
            if slot.default is not None:
                assert slot.accepts(slot.default), (spec.name, slot.name)
    assert REGISTRY["pick_with_arm"].arm is ArmUse.REQUIRED
    assert REGISTRY["bimanual_lift"].uses_both_arms and not REGISTRY["grasp"].uses_both_arms


def test_checked_in_grammar_reference_is_fresh():
    committed = (ROOT / "docs/grammar.md").read_text()
    assert committed == markdown() + "\n", "docs/grammar.md is stale: run `make grammar-docs`"


def test_json_schema_accepts_valid_plans_and_rejects_invalid():
    schema = plan_json_schema()
    jsonschema.Draft202012Validator.check_schema(schema)
    validator = jsonschema.Draft202012Validator(schema)
    for path in sorted((ROOT / "examples/plans").glob("*.yaml")):
        validator.validate(plan_to_dict(parse_plan(path.read_text())))
    bad = {"task": "x", "tree": {"primitive": "grasp", "params": {"force": "high"}}}
    assert not validator.is_valid(bad)
    assert not validator.is_valid({"task": "x", "tree": {"primitive": "teleport"}})
    assert json.dumps(schema)  # serialisable for the LLM request


@pytest.mark.parametrize("name", ["plate_scrub.yaml", "silverware_sort_bimanual.yaml"])
def test_paper_examples_type_check(name):
    plan = parse_plan((ROOT / "examples/plans" / name).read_text())
    assert plan.primitives()
    if "bimanual" in name:
        arms = {arm for _, _, arm in plan.primitives() if arm}
        assert arms == {"left", "right"}
