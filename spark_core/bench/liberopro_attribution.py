"""Which module a camera-only run's LIBERO-PRO failures belong to, from paired trials.

A trial of the camera-only run and a trial of the oracle (privileged `sim`) run with the same task and init state
differ only in perception: same scene, planner, wording, control and success rule. Where the oracle succeeds and
the camera-only run fails, perception is to blame; where both fail, the cause lies elsewhere (planner, control, the
task). The camera-only failure kinds of the perception-attributed pairs say why (label not found, wrong object
grasped so the goal is unmet, the planner found nothing to ground, ...)."""

from __future__ import annotations

from collections import Counter
from collections.abc import Sequence

from .published import LIBEROPRO_CELLS


def _kind(row: dict) -> str:
    """A failed trial's kind: the verdict and, for a failed tree, the module its failure names."""
    v = str(row.get("verdict", "?"))
    return f"{v} ({row['failure']})" if v == "tree_failed" and row.get("failure") else v


def _why(row: dict, limit: int = 90) -> str:
    if row.get("verdict") == "task_unmet":  # its reason only names the goal; the pairing says more
        return "every node's check passed, the goal is false: the keypoints led to the wrong object or place"
    reason = " ".join(str(row.get("reason", "")).split()).replace("|", "/")  # a pipe would split the table cell
    return reason if len(reason) <= limit else reason[: limit - 1] + "…"


def paired_attribution(camera_only: list[dict], oracle: list[dict]) -> dict[str, dict]:
    """Per cell: paired trials, both succeed, perception (only the oracle succeeds), only camera-only succeeds,
    both fail, and the camera-only failure kinds (with one reason each) among the perception-attributed pairs."""
    by_key = {(r["task"], int(r["seed"])): r for r in oracle}
    out: dict[str, dict] = {}
    for cell in LIBEROPRO_CELLS:
        counts: Counter[str] = Counter()
        kinds: Counter[str] = Counter()
        example: dict[str, str] = {}
        for r in camera_only:
            if r["task"].split(":", 1)[0] != cell:
                continue
            o = by_key.get((r["task"], int(r["seed"])))
            if o is None:
                continue
            counts["paired"] += 1
            c, s = bool(r["success"]), bool(o["success"])
            if c and s:
                counts["both"] += 1
            elif s:
                counts["perception"] += 1
                kinds[_kind(r)] += 1
                example.setdefault(_kind(r), _why(r))
            elif c:
                counts["camera_only"] += 1
            else:
                counts["neither"] += 1
        out[cell] = {"counts": counts, "kinds": kinds, "example": example}
    return out


def attribution_table(camera_only: tuple[str, list[dict]], oracle: tuple[str, list[dict]]) -> str:
    """The paired comparison as Markdown: a row per cell; empty when the runs share no trial."""
    result = paired_attribution(camera_only[1], oracle[1])
    if not any(v["counts"]["paired"] for v in result.values()):
        return ""
    lines = [
        f"Failure attribution: `{camera_only[0]}` against `{oracle[0]}` on the trials both ran (same task and init "
        "state: they differ only in perception).",
        "",
        "| cell | paired trials | both succeed | only the oracle succeeds (perception) | only camera-only succeeds "
        "| both fail (not perception) | camera-only failure kinds where perception is to blame (an example reason) |",
        "|---|---|---|---|---|---|---|",
    ]
    for cell, v in result.items():
        n = v["counts"]
        if not n["paired"]:
            continue
        kinds: Sequence[tuple[str, int]] = v["kinds"].most_common()
        why = "; ".join(f"{k} {c}× (\u201c{v['example'][k]}\u201d)" for k, c in kinds[:3]) or "–"
        lines.append(
            f"| {cell} | {n['paired']} | {n['both']} | {n['perception']} | {n['camera_only']} | {n['neither']} "
            f"| {why} |"
        )
    return "\n".join(lines)
