"""`spark bench wording --segmenter`: the recorded table's sim oracle stays the default (its command stays
reproducible); `--segmenter learned` plans and executes with the camera-only segmenter, and the protocol text names
the segmenter and whether it is privileged."""

import argparse

import pytest

from spark_cli import bench as cli
from spark_cli import bench_manifest, build_parser
from spark_core.bench import wording


def test_the_wording_suite_keeps_sim_unless_a_segmenter_is_given_and_other_suites_keep_theirs():
    parse = build_parser().parse_args
    assert cli.wording_segmenter(parse(["bench", "wording", "--plan-only"])) == "sim"
    assert cli.wording_segmenter(parse(["bench", "wording", "--segmenter", "learned"])) == "learned"
    assert cli.wording_segmenter(parse(["bench", "wording", "--segmenter", "sim"])) == "sim"
    assert parse(["bench", "capbench"]).segmenter == "learned"  # the shared default is untouched
    assert parse(["bench", "capbench", "--segmenter", "sim"]).segmenter == "sim"


def test_the_segmenter_reaches_planning_execution_and_the_protocol_text(monkeypatch):
    entry = {"id": "a", "style": "synonym", "suite": "builtin", "task": "block_on_plate", "expect": "goal"}
    row = dict(entry, half="dev", instruction="x", planned=True, correct=True, error="", understood=[])
    used: dict[str, str] = {}
    monkeypatch.setattr(wording, "load", lambda half: [dict(entry, half=half)])
    monkeypatch.setattr(
        wording, "plan_entries", lambda entries, seed, progress, segmenter: used.update(plan=segmenter) or [row]
    )
    seeds_used: list[int] = []
    monkeypatch.setattr(
        wording,
        "execute_sample",
        lambda entries, seeds, progress, segmenter: used.update(execute=segmenter) or seeds_used.append(seeds) or [],
    )
    args = build_parser().parse_args(["bench", "wording", "--half", "dev", "--segmenter", "learned"])
    text = cli._wording(args, "spark bench wording --half dev --segmenter learned")
    assert used == {"plan": "learned", "execute": "learned"}
    args = build_parser().parse_args(["bench", "wording", "--half", "dev", "--trials", "5"])
    cli._wording(args, "spark bench wording --half dev --trials 5")
    assert seeds_used == [wording.EXEC_SEEDS, 5]  # --trials sets the sample's seeds; no silent cap
    # through the command's own set-up (bench_manifest.prepare fills in --trials): still the sample's seeds, not the
    # other suites' 20 trials per task
    args = build_parser().parse_args(["bench", "wording", "--half", "dev"])
    assert bench_manifest.prepare(args) is None and args.trials == wording.EXEC_SEEDS
    args = build_parser().parse_args(["bench", "capbench"])
    assert bench_manifest.prepare(args) is None and args.trials == 20
    assert "perception: learned segmenter (camera-only, not privileged)" in text
    args = build_parser().parse_args(["bench", "wording", "--half", "dev", "--plan-only"])
    text = cli._wording(args, "spark bench wording --half dev --plan-only")
    assert used["plan"] == "sim" and "perception: sim segmenter (PRIVILEGED masks)" in text


@pytest.mark.slow
def test_a_plan_only_run_under_the_learned_segmenter_plans_from_what_the_cameras_show():
    entries = [
        {"id": "a", "style": "synonym", "suite": "builtin", "task": "block_on_plate", "expect": "goal"},
        {"id": "b", "style": "absent", "suite": "builtin", "task": "block_on_plate", "expect": "refuse:absent"},
    ]
    texts = ["set the red block down on the plate", "put the giraffe on the plate"]
    rows = wording.plan_entries(
        [dict(e, instruction=t, half="dev") for e, t in zip(entries, texts)], segmenter="learned"
    )
    assert [r["correct"] for r in rows] == [True, True]
    assert rows[0]["planned"] and not rows[1]["planned"]


def test_an_unknown_segmenter_is_refused_by_the_parser():
    with pytest.raises(SystemExit):
        build_parser().parse_args(["bench", "wording", "--segmenter", "oracle-of-delphi"])
    assert argparse  # (the parser's choices come from the catalog: tests/bench/test_cli_args.py)
