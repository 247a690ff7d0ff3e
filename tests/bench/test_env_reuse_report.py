"""The throughput section reports where a trial's wall time goes (median per phase, from the trials' own
phase timings) and links the before/after profile of a LIBERO-PRO trial."""

from __future__ import annotations

from pathlib import Path

from spark_core.bench import throughput

ROOT = Path(__file__).resolve().parents[2]


def _row(wall: float, rendering: float) -> dict:
    phases = {"setup": 0.5, "perception": 0.1, "rendering": rendering, "planning": 1.0, "simulation": 0.4}
    return {"wall_time_s": wall, "phases_s": phases}


def test_the_section_shows_median_trial_phases_and_links_the_profile():
    rows = [_row(2.0, 1.0), _row(3.0, 1.2), _row(9.0, 4.0)]
    phases = throughput._median_phases(rows)
    assert phases["trial"] == 3.0 and phases["rendering"] == 1.2 and phases["setup"] == 0.5
    run = {"trials": 3, "successes": 2, "wall_s": 10.0, "per_hour": 1080.0, "trial_phases_s": phases}
    result = {
        "trials_per_task": 1,
        "workers": 2,
        "segmenter": "sim",
        "suites": {"liberopro": {"tasks": 3, "planner": "rules", "runs": {"local": run}, "manifest": {"id": "ab"}}},
    }
    text = throughput.section(result, "spark bench throughput")
    assert "| liberopro | local | 3.00 s | 0.50 s | 0.10 s | 1.20 s | 1.00 s | 0.40 s |" in text
    assert f"]({throughput.PROFILE_DOC})" in text
    assert (ROOT / throughput.PROFILE_DOC).is_file()
