"""LIBERO-PRO per cell: our runs side by side, each labelled with its protocol and split into development and
held-out init states, with 95 % Wilson intervals, next to the published rows of the SPARK paper's table.

A run is the row list `spark bench liberopro --json FILE` writes (every row carries its protocol), so runs made at
different times, with different segmenters, are compared from their own records, never retyped by hand."""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

from .liberopro_attribution import attribution_table
from .published import LIBEROPRO_CELLS, LIBEROPRO_MEAN
from .report import footer, pct, wilson
from .run_file import read_rows
from .splits import SPLITS

# The SPARK paper's LIBERO-PRO table: mean over the six position and task cells (success %). Only the Adaptive
# row's per-cell figures are known here (published.LIBEROPRO_CELLS); the others are means.
PUBLISHED_MEANS: tuple[tuple[str, str], ...] = (
    ("SPARK Fair (paper)", "31.9"),
    ("SPARK +BDDL (paper)", "31.2"),
    ("SPARK Adaptive (paper)", LIBEROPRO_MEAN),
    ("RATs (paper)", "43.8"),
    ("CaP-Agent0 (paper)", "18.2"),
    ("CaP-Agent0 re-evaluated (paper)", "23.2"),
    ("pi0.5 (paper)", "12.8"),
    ("MolmoAct2 (paper)", "18.6"),
)


class RunError(ValueError):
    """A run file that is not a LIBERO-PRO run (names the file and what is wrong)."""


def load_run(path: Path) -> list[dict]:
    """The rows of one `spark bench liberopro --json` file (gzipped when its name ends in .gz); RunError naming the
    file when they are not that."""
    try:
        rows = read_rows(path)
    except (OSError, ValueError, EOFError) as e:
        raise RunError(f"{path}: cannot read a run ({e})") from None
    if not isinstance(rows, list) or not rows or not all(isinstance(r, dict) for r in rows):
        raise RunError(f"{path}: expected the JSON list of trial rows `spark bench liberopro --json` writes")
    for i, r in enumerate(rows):
        missing = [k for k in ("task", "seed", "success", "protocol") if k not in r]
        if missing:
            raise RunError(f"{path}: row {i} has no {', '.join(missing)}")
        if r["task"].split(":", 1)[0] not in LIBEROPRO_CELLS:
            raise RunError(f"{path}: row {i} is task {r['task']!r}, not a LIBERO-PRO cell's")
    return rows


def run_label(rows: list[dict]) -> str:
    """The protocol a run's column is labelled with: segmenter (privileged or camera-only), planner, wording."""
    p = rows[0]["protocol"]
    seg = p.get("segmenter", "?")
    kind = "oracle, PRIVILEGED" if p.get("privileged") else "camera-only"
    planning = p.get("planning") or {}
    planner = planning.get("source") or "?"
    if planning.get("model"):
        planner += f" {planning['model']}"
    wording = "official wording" if "official" in str(p.get("wording", "")) else str(p.get("wording", "?"))
    return f"{seg} ({kind}), {planner} planner, {wording}"


def _split_of(seed: int) -> str:
    return "dev" if seed in SPLITS["dev"] else "held-out"


def _tasks(rows: list[dict]) -> str:
    n = len({r["task"] for r in rows})
    return f"{n} task{'s' if n != 1 else ''}"


def rate_with_interval(rows: list[dict]) -> str:
    """'success [95 % Wilson interval] (trials)' of some trial rows; '–' for none."""
    if not rows:
        return "–"
    k = sum(bool(r["success"]) for r in rows)
    lo, hi = wilson(k, len(rows))
    return f"{pct(k / len(rows))} [{100 * lo:.1f}–{100 * hi:.1f}] ({len(rows)})"


def table(runs: Sequence[tuple[str, list[dict]]]) -> str:
    """As the paper's table: one row per system, a column per cell and the mean over cells. Each of our runs
    gives a row per part it has (development, held-out init states) and one for all of it when it has both;
    the published rows follow (per cell where known here, the mean always)."""
    parts: list[tuple[str, list[dict]]] = []
    for label, rows in runs:
        split = {s: [r for r in rows if _split_of(int(r["seed"])) == s] for s in ("dev", "held-out")}
        present = [(s, rs) for s, rs in split.items() if rs]
        for s, rs in present:
            seeds = sorted({int(r["seed"]) for r in rs})
            parts.append((f"{label}: {s}, {_tasks(rs)}, init states {seeds[0]}–{seeds[-1]}", rs))
        if len(present) > 1:
            parts.append((f"{label}: all, {_tasks(rows)}", rows))
    cells = list(LIBEROPRO_CELLS)
    lines = ["| system (protocol) | " + " | ".join(cells) + " | mean over cells |", "|" + "---|" * (len(cells) + 2)]
    for label, rows in parts:
        values, rates = [], []
        for cell in cells:
            rs = [r for r in rows if r["task"].split(":", 1)[0] == cell]
            values.append(rate_with_interval(rs))
            if rs:
                rates.append(sum(bool(r["success"]) for r in rs) / len(rs))
        mean = f"**{pct(sum(rates) / len(rates))}**" if len(rates) == len(cells) else "– (not every cell)"
        lines.append(f"| {label} | " + " | ".join(values) + f" | {mean} |")
    for name, mean_pct in PUBLISHED_MEANS:
        per_cell = [f"{LIBEROPRO_CELLS[c]} %" if name.startswith("SPARK Adaptive") else "–" for c in cells]
        lines.append(f"| {name} | " + " | ".join(per_cell) + f" | **{mean_pct} %** |")
    return "\n".join(lines)


def _attributions(runs: Sequence[tuple[Path, list[dict]]]) -> str:
    """For each camera-only run, the paired comparison with the oracle run sharing most of its trials."""
    oracles = [(str(p), rows) for p, rows in runs if rows[0]["protocol"].get("privileged")]
    out = []
    for path, rows in runs:
        if rows[0]["protocol"].get("privileged") or not oracles:
            continue
        keys = {(r["task"], int(r["seed"])) for r in rows}
        best = max(oracles, key=lambda o: len(keys & {(r["task"], int(r["seed"])) for r in o[1]}))
        text = attribution_table((str(path), rows), best)
        if text:
            out.append(text)
    return "".join(t + "\n\n" for t in out)


def section(runs: Sequence[tuple[Path, list[dict]]], command: str) -> str:
    labelled = [(run_label(rows), rows) for _, rows in runs]
    sources = "; ".join(
        f"`{path}`: {label}, {len(rows)} trials, seeds {min(r['seed'] for r in rows)}–{max(r['seed'] for r in rows)}"
        + (f", run manifest `{rows[0]['manifest_id']}`" if rows[0].get("manifest_id") else "")
        for (path, rows), (label, _) in zip(runs, labelled, strict=True)
    )
    return (
        table(labelled)
        + "\n\nOur entries: success [95 % Wilson interval] (trials). Mean over cells: the unweighted mean of "
        "the six cell rates, as the paper reports it.\n\n"
        + _attributions(runs)
        + footer(
            command,
            "LIBERO-PRO, six cells (libero_{spatial,object,goal} x position swap / task perturbation); a trial's seed "
            "is its init-state index: development init states 0–9, held-out 10–49 (spark_core/bench/splits.py); "
            "success = the task's predicate within the time limit and the behavior tree succeeded; our runs: "
            + sources
            + "; published rows: the SPARK paper's LIBERO-PRO table (Gemini planner + SAM3, or the cited baselines), "
            "not re-run here",
        )
    )
