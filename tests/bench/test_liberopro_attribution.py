"""Paired failure attribution: a camera-only run against the oracle run on the same tasks and init states."""

from __future__ import annotations

from spark_core.bench.liberopro_attribution import attribution_table, paired_attribution

TASK = "libero_object_swap:pick_up_the_alphabet_soup_and_place_it_in_the_basket"
OTHER = "libero_goal_task:open_the_middle_drawer_of_the_cabinet"


def _row(task: str, seed: int, success: bool, verdict: str = "success", failure: str | None = None, reason=""):
    return {"task": task, "seed": seed, "success": success, "verdict": verdict, "failure": failure, "reason": reason}


def test_pairs_by_task_and_init_state_and_blames_perception_only_where_the_oracle_succeeds():
    oracle = [_row(TASK, s, s != 3) for s in range(5)] + [_row(OTHER, 0, False, "task_unmet")]
    camera = [
        _row(TASK, 0, True),
        _row(TASK, 1, False, "task_unmet"),
        _row(TASK, 2, False, "tree_failed", "perception", "label 'basket' not resolved | no detection"),
        _row(TASK, 3, False, "timeout"),  # the oracle failed too: not perception
        _row(TASK, 7, False, "timeout"),  # the oracle never ran init state 7: not paired
        _row(OTHER, 0, True),
    ]
    result = paired_attribution(camera, oracle)
    n = result["libero_object_swap"]["counts"]
    assert (n["paired"], n["both"], n["perception"], n["neither"], n["camera_only"]) == (4, 1, 2, 1, 0)
    assert result["libero_object_swap"]["kinds"] == {"task_unmet": 1, "tree_failed (perception)": 1}
    assert result["libero_goal_task"]["counts"]["camera_only"] == 1
    text = attribution_table(("learned.json", camera), ("sim.json", oracle))
    row = next(line for line in text.splitlines() if line.startswith("| libero_object_swap"))
    assert row.count("|") == 8  # the reason's pipe does not split the row
    assert "tree_failed (perception) 1×" in row and "wrong object or place" in row


def test_no_shared_trials_gives_no_table():
    assert attribution_table(("a", [_row(TASK, 0, True)]), ("b", [_row(TASK, 1, True)])) == ""
