"""The paper's two example plans (examples/plans/, the paper's format and slots) validate and run in simulation
through `spark run --plan`: the sponge scrub on `scrub_plate`, the bimanual silverware plan on `silverware_tray`
(a fork, a knife and a tray on the two-Panda cell)."""

from __future__ import annotations

from pathlib import Path

import pytest

from spark_cli import main

PLANS = Path(__file__).resolve().parents[1] / "examples" / "plans"


@pytest.mark.parametrize(
    ("plan", "labels"),
    [("plate_scrub.yaml", "sponge, plate"), ("silverware_sort_bimanual.yaml", "fork, knife, tray")],
)
def test_the_papers_plans_validate(plan, labels, capsys):
    assert main(["validate", str(PLANS / plan)]) == 0
    assert f"labels {labels}" in capsys.readouterr().out


def test_the_silverware_plan_uses_the_papers_bimanual_slots():
    from spark_core.grammar import parse_plan

    plan = parse_plan((PLANS / "silverware_sort_bimanual.yaml").read_text())
    prims = {(n.primitive, arm): n.params for _, n, arm in plan.primitives()}  # arm: inherited from the branch
    assert prims[("pick_with_arm", "left")]["target_width"] == 0.012
    assert prims[("pick_with_arm", "right")]["prefer_angled"] is False
    assert "target_label" not in prims[("place_with_arm", "left")]  # sets down where the hand is
    assert prims[("place_with_arm", "right")]["tilt_angle"] == 0.0


@pytest.mark.parametrize(
    ("task", "plan", "segmenter"),
    [
        ("silverware_tray", "silverware_sort_bimanual.yaml", "privileged-keypoints"),
        pytest.param("silverware_tray", "silverware_sort_bimanual.yaml", "sim", marks=pytest.mark.slow),
        pytest.param("scrub_plate", "plate_scrub.yaml", "sim", marks=pytest.mark.slow),
    ],
)
def test_the_papers_plans_run(task, plan, segmenter, capsys):
    code = main(["run", task, "--plan", str(PLANS / plan), "--segmenter", segmenter, "--seed", "2", "--no-store"])
    out = capsys.readouterr().out
    assert code == 0 and "verdict: success; task predicate: true" in out, out[-2000:]
