"""The formats a planner actually returns: YAML, JSON, code fences, JSON holding YAML text."""

import json
from pathlib import Path

import pytest

from spark_core.grammar import parse_plan, plan_to_dict, to_yaml

ROOT = Path(__file__).resolve().parents[2]
YAML_TEXT = (ROOT / "examples/plans/plate_scrub.yaml").read_text()
REFERENCE = parse_plan(YAML_TEXT)


@pytest.mark.parametrize(
    "text",
    [
        YAML_TEXT,
        json.dumps(plan_to_dict(REFERENCE)),
        "Here is the plan:\n```yaml\n" + YAML_TEXT + "```\nLet me know.",
        "```json\n" + json.dumps(plan_to_dict(REFERENCE), indent=2) + "\n```",
        "```\n" + YAML_TEXT + "```",
        json.dumps({"plan": YAML_TEXT}),
        json.dumps({"plan": plan_to_dict(REFERENCE)}),
        json.dumps({"response": {"plan": plan_to_dict(REFERENCE)}}),
        json.dumps(YAML_TEXT),
        "\ufeff" + YAML_TEXT,
        YAML_TEXT.encode("utf-8"),
    ],
    ids=[
        "yaml",
        "json",
        "fenced-yaml-with-prose",
        "fenced-json",
        "bare-fence",
        "json-holding-yaml",
        "json-wrapper",
        "nested-wrapper",
        "quoted-yaml",
        "bom",
        "bytes",
    ],
)
def test_wrapped_formats_parse_to_the_same_plan(text):
    assert parse_plan(text) == REFERENCE


def test_canonical_yaml_is_stable():
    once = to_yaml(REFERENCE)
    assert to_yaml(parse_plan(once)) == once
    assert once.startswith("task: scrub the plate with the sponge\ntree:\n  type: sequence\n")


def test_defaults_apply_without_being_serialised():
    plan = parse_plan("task: t\ntree: {primitive: move_to_keypoint, params: {keypoint_label: cup}}")
    assert plan.tree.args == {"keypoint_label": "cup", "offset_x": 0.0, "offset_y": 0.0, "offset_z": 0.10}
    assert "offset_z" not in to_yaml(plan)


def test_numbers_are_normalised_to_float():
    plan = parse_plan("task: t\ntree: {primitive: grasp, params: {force: 40}}")
    assert plan.tree.params["force"] == 40.0 and isinstance(plan.tree.params["force"], float)
