"""The benchmark path's memory regime: `spark bench --plan-library FILE` gives an LLM planner few-shot examples
from a fixed library (read-only for the run), and the run manifest records the library's hash."""

from __future__ import annotations

import json

from spark_core.planning.plan_library import PlanLibrary

EXAMPLE = "raise the little cube off the table"
EXAMPLE_PLAN = "task: lift\ntree:\n  type: sequence\n  children:\n  - type: pick\n    params: {target: cube}\n"


def test_a_read_only_library_gives_examples_and_never_grows(tmp_path):
    path = tmp_path / "library.jsonl"
    PlanLibrary(path).add(EXAMPLE, EXAMPLE_PLAN)
    frozen = PlanLibrary(path, read_only=True)
    frozen.add("stack the blocks", "task: x\ntree: {}\n")
    assert [e["instruction"] for e in frozen.entries()] == [EXAMPLE]
    assert frozen.examples("lift the block") == ((EXAMPLE, EXAMPLE_PLAN),)


def test_spark_bench_gives_the_llm_planner_the_librarys_examples_and_records_it(tmp_path):
    """One builtin trial with the gemini client against the loopback stand-in: the BT call's prompt carries the
    library's example, the library is unchanged after a successful trial, the manifest names its hash."""
    from spark_cli import main
    from spark_core.trace import TraceStore

    path = tmp_path / "library.jsonl"
    PlanLibrary(path).add(EXAMPLE, EXAMPLE_PLAN)
    before = path.read_text()
    store = f"sqlite:///{tmp_path / 'trace.db'}"
    manifest = tmp_path / "manifest.json"
    code = main(
        ["bench", "builtin", "--planner", "gemini", "--llm-loopback", "--segmenter", "sim", "--tasks", "lift_block"]
        + ["--trials", "1", "--plan-library", str(path), "--store", store, "--manifest-out", str(manifest)]
    )
    assert code == 0
    assert path.read_text() == before
    memory = json.loads(manifest.read_text())["run"]["memory"]
    assert memory["plan_library"] == "on" and memory["plans"] == 1 and len(memory["sha256"]) == 64
    _, (trial,) = TraceStore(store).list_trials(limit=5)
    record = TraceStore(store).get_trial(trial["id"])
    prompts = [json.dumps(c.get("prompt", "")) for c in record["protocol"]["planning"]["calls"]]
    assert any(EXAMPLE in p for p in prompts), prompts


def test_a_missing_library_file_is_refused_by_name(tmp_path, capsys):
    from spark_cli import main

    missing = tmp_path / "nope.jsonl"
    assert main(["bench", "builtin", "--tasks", "lift_block", "--trials", "1", "--plan-library", str(missing)]) == 2
    assert f"--plan-library: no such file {missing}" in capsys.readouterr().err
