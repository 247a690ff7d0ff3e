"""`spark bench console`'s code path on a tiny store, one sample of each measurement: every figure is measured
(a real browser, server, trial worker and 3D view) and the section is written. No timing is asserted: the
figures are for BENCHMARKS.md."""

import shutil
from pathlib import Path

import pytest

from spark_cli.console_bench import console

ROOT = Path(__file__).resolve().parents[2]


@pytest.mark.skipif(not (ROOT / "web" / "dist" / "index.html").is_file(), reason="front end not built (make install)")
@pytest.mark.skipif(not (shutil.which("chromium-headless-shell") or shutil.which("chromium")), reason="no chromium")
def test_every_measurement_is_taken_and_reported():
    r = console.run(runs=2, trials=1, store_size=20)
    assert len(r["run_to_running_s"]) == 2 and min(r["run_to_running_s"]) > 0
    assert len(r["latency_s"]) >= 4 and all(x > 0 for x in r["latency_s"])  # every live event reached the screen
    assert r["fps_live"][0] > 0 and r["fps_replay"][0] > 0
    assert len(r["dashboard_s"]) == len(r["history_s"]) == 2
    text = console.section(r, "spark bench console")
    rows = [line for line in text.splitlines() if line.startswith("| ") and "measurement" not in line]
    assert len(rows) == 7 and "20 trials in the store" in text and "load average" in text
