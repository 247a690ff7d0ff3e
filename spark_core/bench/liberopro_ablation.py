"""The SPARK paper's ablations on LIBERO-PRO, measured here: adaptive prompts and recovery, each switched off
against the full system, on the same tasks and init states.

Each run is the row list `spark bench liberopro --json` writes; a run's configuration is read from its rows'
protocol (adaptive prompts on/off, recovery on/off), never from its file name. The two ablation runs must hold the same
trials (task and init state), so a difference is the switch and nothing else; the full system's run holds them too,
or more (the whole development run), and is then read on those trials alone."""

from __future__ import annotations

from collections import Counter
from collections.abc import Sequence
from pathlib import Path

from .liberopro_table import RunError, rate_with_interval, run_label
from .report import footer

SUITES = ("libero_spatial", "libero_object", "libero_goal")
# The paper's ablation effects (percentage points, switch on minus off): adaptive prompts on the spatial and
# object suites, recovery over the benchmark.
PAPER_EFFECTS: dict[str, dict[str, float]] = {
    "adaptive prompts": {"libero_spatial": 27.7, "libero_object": 10.0},
    "recovery": {"all": 5.0},
}
CONFIGS = ("full", "adaptive prompts off", "recovery off")


def configuration(rows: list[dict]) -> str:
    """Which of CONFIGS a run is, from its protocol; RunError when it switches both off."""
    p = rows[0]["protocol"]
    adaptive, recovery = bool(p.get("adaptive_prompts")), p.get("recovery") != "off"
    if adaptive and recovery:
        return "full"
    if recovery:
        return "adaptive prompts off"
    if adaptive:
        return "recovery off"
    raise RunError("a run with both adaptive prompts and recovery off is no ablation of one switch")


def _rate(rows: list[dict]) -> float | None:
    return sum(bool(r["success"]) for r in rows) / len(rows) if rows else None


def _in(rows: list[dict], suite: str) -> list[dict]:
    return rows if suite == "all" else [r for r in rows if r["task"].startswith(suite + "_")]


def table(runs: dict[str, list[dict]]) -> str:
    cols = [*SUITES, "all"]
    lines = ["| configuration | " + " | ".join(cols) + " |", "|" + "---|" * (len(cols) + 1)]
    for name in CONFIGS:
        lines.append(f"| {name} | " + " | ".join(rate_with_interval(_in(runs[name], s)) for s in cols) + " |")
    for switch, off in (("adaptive prompts", "adaptive prompts off"), ("recovery", "recovery off")):
        ours = []
        for s in cols:
            on_rate, off_rate = _rate(_in(runs["full"], s)), _rate(_in(runs[off], s))
            ours.append("–" if on_rate is None or off_rate is None else f"{100 * (on_rate - off_rate):+.1f} pts")
        lines.append(f"| effect of {switch} (on − off), ours | " + " | ".join(ours) + " |")
        paper = PAPER_EFFECTS[switch]
        lines.append(
            f"| effect of {switch}, paper | "
            + " | ".join(f"{paper[s]:+.1f} pts" if s in paper else "–" for s in cols)
            + " |"
        )
    return "\n".join(lines)


def section(runs: Sequence[tuple[Path, list[dict]]], command: str) -> str:
    by_config: dict[str, tuple[Path, list[dict]]] = {}
    for path, rows in runs:
        name = configuration(rows)
        if name in by_config:
            raise RunError(f"{path} and {by_config[name][0]} are both the {name!r} configuration")
        by_config[name] = (path, rows)
    missing = [c for c in CONFIGS if c not in by_config]
    if missing:
        raise RunError(f"no run for: {', '.join(missing)} (give one run of each of: {', '.join(CONFIGS)})")
    keys = {c: {(r["task"], int(r["seed"])) for r in rows} for c, (_, rows) in by_config.items()}
    sampled = keys[CONFIGS[1]]
    # the full system's run may be a larger one (the whole development run): its rows on the sampled trials are
    # the same trials the ablations ran
    restricted = keys["full"] > sampled and all(keys[c] == sampled for c in CONFIGS[1:])
    if restricted:
        path, rows = by_config["full"]
        by_config["full"] = (path, [r for r in rows if (r["task"], int(r["seed"])) in sampled])
        keys["full"] = sampled
    if len({frozenset(k) for k in keys.values()}) != 1:
        raise RunError("the runs hold different trials (task and init state): an ablation compares the same ones")
    rows_of = {c: rows for c, (_, rows) in by_config.items()}
    full = rows_of["full"]
    per_cell = Counter(t.split(":", 1)[0] for t in {r["task"] for r in full})
    sample = (
        f"{next(iter(per_cell.values()))} in each of the {len(per_cell)} cells"
        if len(set(per_cell.values())) == 1
        else ", ".join(f"{c} {n}" for c, n in sorted(per_cell.items()))
    )
    seeds = sorted({int(r["seed"]) for r in full})
    sources = "; ".join(
        f"{c}: `{p}`"
        + (" (its rows on the sampled trials)" if c == "full" and restricted else "")
        + (f", run manifest `{rows[0]['manifest_id']}`" if rows[0].get("manifest_id") else "")
        for c, (p, rows) in by_config.items()
    )
    won = {c: {(r["task"], int(r["seed"])) for r in rows if r["success"]} for c, rows in rows_of.items()}
    flips = ", ".join(f"{c} {len(won[c] ^ won['full'])}" for c in CONFIGS[1:])
    return (
        table(rows_of)
        + "\n\nEntries: success [95 % Wilson interval] (trials); effects in percentage points. With these trial "
        f"counts an effect under about 10 points is within noise. Trials whose success differs from the full "
        f"run's: {flips}.\n\n"
        + footer(
            command,
            f"LIBERO-PRO, {len({r['task'] for r in full})} tasks ({sample}), init states {seeds[0]}–{seeds[-1]} "
            f"(development); system: {run_label(full)}; "
            "full = adaptive prompts on (label + 3 variants) and recovery on (tiers 1-2, 2 retries); each ablation "
            "switches one off and keeps everything else; runs: " + sources + "; the paper's effects are its "
            "ablation figures (Gemini planner + SAM3), not re-run here",
        )
    )
