"""The ablation table: configurations read from the runs' protocols, effects as on minus off, same trials only."""

from __future__ import annotations

from pathlib import Path

import pytest

from spark_core.bench.liberopro_ablation import configuration, section
from spark_core.bench.liberopro_table import RunError

SPATIAL = "libero_spatial_swap:pick_up_the_black_bowl_between_the_plate_and_the_ramekin_and_place_it_on_the_plate"
OBJECT = "libero_object_task:pick_up_the_alphabet_soup_and_place_it_in_the_basket"


def _run(adaptive: bool, recovery: bool, wins: dict[str, int], seeds=range(10)) -> list[dict]:
    protocol = {
        "segmenter": "learned",
        "privileged": False,
        "adaptive_prompts": adaptive,
        "recovery": "tiers 1-2, 2 retries" if recovery else "off",
        "planning": {"source": "rules"},
        "wording": "official",
    }
    return [
        {"task": t, "seed": s, "success": s < wins[t], "protocol": protocol} for t in (SPATIAL, OBJECT) for s in seeds
    ]


def test_effects_are_full_minus_the_switched_off_run_per_suite():
    runs = [
        (Path("off_rec.json"), _run(True, False, {SPATIAL: 5, OBJECT: 4})),
        (Path("full.json"), _run(True, True, {SPATIAL: 6, OBJECT: 4})),
        (Path("off_ad.json"), _run(False, True, {SPATIAL: 2, OBJECT: 3})),
    ]
    text = section(runs, "spark bench liberopro-ablation")
    adaptive = next(line for line in text.splitlines() if line.startswith("| effect of adaptive prompts (on"))
    assert adaptive.split(" | ")[1:3] == ["+40.0 pts", "+10.0 pts"]  # spatial 6-2 of 10, object 4-3 of 10
    assert adaptive.rstrip(" |").endswith("+25.0 pts")  # all: 10/20 against 5/20
    paper = next(line for line in text.splitlines() if line.startswith("| effect of adaptive prompts, paper"))
    assert "+27.7 pts" in paper and "+10.0 pts" in paper
    recovery = next(line for line in text.splitlines() if line.startswith("| effect of recovery (on"))
    assert recovery.rstrip(" |").endswith("+5.0 pts")  # 10/20 against 9/20
    assert "full: `full.json`" in text
    assert "differs from the full run's: adaptive prompts off 5, recovery off 1." in text


def test_configuration_comes_from_the_protocol_and_both_off_is_refused():
    assert configuration(_run(False, True, {SPATIAL: 0, OBJECT: 0})) == "adaptive prompts off"
    with pytest.raises(RunError, match="both"):
        configuration(_run(False, False, {SPATIAL: 0, OBJECT: 0}))


def test_runs_over_different_trials_or_a_missing_configuration_are_refused():
    full = _run(True, True, {SPATIAL: 1, OBJECT: 1})
    with pytest.raises(RunError, match="different trials"):
        section(
            [
                (Path("a"), full),
                (Path("b"), _run(False, True, {SPATIAL: 1, OBJECT: 1}, seeds=range(5))),
                (Path("c"), _run(True, False, {SPATIAL: 1, OBJECT: 1})),
            ],
            "x",
        )
    with pytest.raises(RunError, match="no run for: recovery off"):
        section([(Path("a"), full), (Path("b"), _run(False, True, {SPATIAL: 1, OBJECT: 1}))], "x")


def test_a_full_run_over_more_trials_is_read_on_the_ablations_trials_alone():
    """The whole development run serves as the full system: only its rows on the sampled trials count."""
    sampled = {SPATIAL: 6, OBJECT: 4}
    other = SPATIAL.replace("between", "beside")
    full = _run(True, True, sampled) + [
        dict(r, task=other) for r in _run(True, True, {SPATIAL: 0, OBJECT: 0}) if r["task"] == SPATIAL
    ]  # 10 extra trials of another task, all failed: they must not dilute the full system's rates
    runs = [
        (Path("dev.json"), full),
        (Path("off_ad.json"), _run(False, True, {SPATIAL: 2, OBJECT: 3})),
        (Path("off_rec.json"), _run(True, False, {SPATIAL: 5, OBJECT: 4})),
    ]
    text = section(runs, "spark bench liberopro-ablation")
    full_row = next(line for line in text.splitlines() if line.startswith("| full |"))
    assert full_row.rstrip(" |").endswith("50.0 % [29.9–70.1] (20)")  # 10 of the 20 sampled trials
    assert "full: `dev.json` (its rows on the sampled trials)" in text
    assert "2 tasks (1 in each of the 2 cells)" in text
    # the ablation runs themselves must still agree with each other
    with pytest.raises(RunError, match="different trials"):
        section([runs[0], runs[1], (Path("c"), _run(True, False, {SPATIAL: 1, OBJECT: 1}, seeds=range(5)))], "x")


def test_the_protocol_line_counts_the_sampled_tasks_per_cell():
    def run(adaptive: bool, recovery: bool) -> list[dict]:
        rows = _run(adaptive, recovery, {SPATIAL: 3, OBJECT: 3})
        return rows + [dict(r, task=r["task"].replace("between", "beside")) for r in rows if r["task"] == SPATIAL]

    text = section([(Path("f"), run(True, True)), (Path("a"), run(False, True)), (Path("r"), run(True, False))], "x")
    assert "3 tasks (libero_object_task 1, libero_spatial_swap 2)" in text and "first three" not in text
