"""The LIBERO-PRO per-cell comparison: runs read from `spark bench liberopro --json` files, split into development
and held-out init states with Wilson intervals, next to the published rows; bad run files named."""

from __future__ import annotations

import json

import pytest

from spark_cli import main
from spark_core.bench.liberopro_table import RunError, load_run, table
from spark_core.bench.published import LIBEROPRO_CELLS
from spark_core.bench.run_file import write_rows

PROTOCOL = {"segmenter": "learned", "privileged": False, "planning": {"source": "rules"}, "wording": "official"}


def _rows(successes_by_seed: dict[int, bool]) -> list[dict]:
    return [
        {"task": f"{cell}:some_task", "seed": seed, "success": ok, "protocol": PROTOCOL}
        for cell in LIBEROPRO_CELLS
        for seed, ok in successes_by_seed.items()
    ]


def test_a_run_with_both_splits_gets_a_row_each_and_one_for_all():
    rows = _rows({0: True, 1: False, 10: True, 11: True, 12: True, 13: False})
    out = table([("learned (camera-only), rules planner, official wording", rows)])
    lines = {line.split(" | ")[0].lstrip("| "): line for line in out.splitlines()}
    dev = lines["learned (camera-only), rules planner, official wording: dev, 6 tasks, init states 0–1"]
    held = lines["learned (camera-only), rules planner, official wording: held-out, 6 tasks, init states 10–13"]
    everything = lines["learned (camera-only), rules planner, official wording: all, 6 tasks"]
    # 1 of 2 -> 50 % with Wilson [9.5, 90.5]; 3 of 4 -> 75 % [30.1, 95.4]; 4 of 6 per cell overall
    assert "50.0 % [9.5–90.5] (2)" in dev and dev.endswith("**50.0 %** |")
    assert "75.0 % [30.1–95.4] (4)" in held and held.endswith("**75.0 %** |")
    assert "66.7 %" in everything and "(6)" in everything
    assert "| SPARK Adaptive (paper) | 43.4 % |" in out and "| pi0.5 (paper) |" in out


def test_a_run_missing_a_cell_has_no_mean():
    rows = [r for r in _rows({0: True}) if not r["task"].startswith("libero_goal_task")]
    out = table([("x", rows)])
    row = next(line for line in out.splitlines() if line.startswith("| x: dev"))
    assert "– (not every cell)" in row and row.count("100.0 %") == 5


@pytest.mark.parametrize(
    "content, message",
    [
        ("not json", "cannot read a run"),
        (json.dumps({"rows": []}), "expected the JSON list"),
        (json.dumps([{"task": "libero_goal_swap:x", "seed": 0}]), "row 0 has no success, protocol"),
        (json.dumps([{"task": "lift_block", "seed": 0, "success": True, "protocol": {}}]), "not a LIBERO-PRO cell"),
    ],
)
def test_bad_run_files_are_named_with_what_is_wrong(tmp_path, content, message):
    path = tmp_path / "run.json"
    path.write_text(content)
    with pytest.raises(RunError, match=message) as e:
        load_run(path)
    assert str(path) in str(e.value)


def test_cli_asks_for_runs_and_writes_the_section(tmp_path, capsys):
    assert main(["bench", "liberopro-table"]) == 2
    assert "--runs" in capsys.readouterr().err
    run = tmp_path / "learned.json"
    run.write_text(json.dumps(_rows({10: True, 11: False})))
    out = tmp_path / "BENCHMARKS.md"
    assert main(["bench", "liberopro-table", "--runs", str(run), "--write", str(out)]) == 0
    text = out.read_text()
    assert "## LIBERO-PRO per cell: our runs and the published rows" in text
    assert "held-out, 6 tasks, init states 10–11" in text and str(run) in text


def test_a_gzipped_run_reads_as_the_plain_one_and_writes_the_same_bytes_each_time(tmp_path):
    rows = [
        {"task": "libero_goal_swap:turn_on_the_stove", "seed": 3, "success": True, "protocol": {"segmenter": "sim"}}
    ]
    plain, packed = tmp_path / "run.json", tmp_path / "run.json.gz"
    write_rows(plain, rows)
    write_rows(packed, rows)
    assert packed.read_bytes()[:2] == b"\x1f\x8b"  # gzip's magic: compressed, not JSON text
    assert load_run(packed) == load_run(plain) == rows
    first = packed.read_bytes()
    write_rows(packed, rows)  # no timestamp in the header: a re-written run is no change for git
    assert packed.read_bytes() == first


def test_a_truncated_gzipped_run_is_named_with_what_is_wrong(tmp_path):
    path = tmp_path / "run.json.gz"
    write_rows(path, [{"task": "libero_goal_swap:x", "seed": 0, "success": True, "protocol": {}}])
    path.write_bytes(path.read_bytes()[:20])
    with pytest.raises(RunError, match="cannot read a run") as e:
        load_run(path)
    assert str(path) in str(e.value)
