"""Reference plans on the builtin tasks with the privileged resolver: measures control and primitives alone."""

from __future__ import annotations

import statistics
from typing import Callable, Iterable

from ..sim.tasks import TASKS
from ..execution import RecoveryPolicy
from .report import footer, pct, wilson
from .trial import PerceptionConfig, TrialOutcome, run_reference_trial


def protocol(perception: PerceptionConfig, recovery: RecoveryPolicy, planner: str = "reference") -> str:
    rec = "recovery off" if recovery.max_retries == 0 else f"recovery tiers 1-2 on ({recovery.max_retries} retries per node), replan off"
    who = ("hand-written reference plan per task (no LLM; the planner saw nothing)" if planner == "reference" else
           f"{planner} planner, one call per trial on the env's instruction; it received the instruction and what "
           "perception found for the instruction's phrases (no object-name dictionary)")
    return (f"planner: {who}; resolver: {perception.describe()}; {rec}; success: the task's predicate over simulator state")


def _one(args: tuple) -> dict:
    task, seed, perception, recovery, embodiment, store_url, batch_id, planner = args
    store = None
    if store_url:
        from ..trace import TraceStore

        store = TraceStore(store_url, migrate=False)  # the driver migrated it
    return run_reference_trial(TASKS[task], seed, recovery=recovery, perception=perception, embodiment=embodiment,
                               store=store, batch_id=batch_id, planner=planner).row()


def run(tasks: Iterable[str], trials: int, seed: int = 0, workers: int = 1,
        progress: Callable[[dict], None] | None = None, perception: PerceptionConfig = PerceptionConfig(),
        recovery: RecoveryPolicy = RecoveryPolicy(), embodiment: str | None = None, executor: str = "local",
        ray_address: str | None = None, store_url: str | None = None, planner: str = "reference") -> list[dict]:
    """Every task x seed; `executor` local (process pool of `workers`) or ray (see bench.executors). With
    `store_url` every trial is recorded in that trace store under one batch (watch it in the console)."""
    from .executors import run_jobs

    batch_id = None
    tasks = list(tasks)
    if store_url:
        import uuid

        from ..trace import TraceStore

        batch_id = f"bench-{uuid.uuid4().hex[:10]}"
        TraceStore(store_url).create_batch(batch_id, {"suite": "bench", "tasks": tasks, "trials": trials, "seed": seed,
                                                      "resolver": perception.resolver, "executor": executor})
    jobs = [(t, seed + k, perception, recovery, embodiment, store_url, batch_id, planner)
            for t in tasks for k in range(trials)]
    return run_jobs(_one, jobs, executor, workers, ray_address, progress)


def table(rows: list[dict]) -> str:
    lines = ["| task | success | 95 % CI | trials | median sim time | median wall time | failures |",
             "|---|---|---|---|---|---|---|"]
    for task in dict.fromkeys(r["task"] for r in rows):
        rs = [r for r in rows if r["task"] == task]
        k = sum(r["success"] for r in rs)
        lo, hi = wilson(k, len(rs))
        fails = {}
        for r in rs:
            if not r["success"]:
                key = r["failure"] or "predicate false"
                fails[key] = fails.get(key, 0) + 1
        lines.append(
            f"| {task} | {pct(k / len(rs))} | {pct(lo)} – {pct(hi)} | {len(rs)} | "
            f"{statistics.median(r['sim_time_s'] for r in rs):.1f} s | {statistics.median(r['wall_time_s'] for r in rs):.2f} s | "
            f"{', '.join(f'{v}× {k}' for k, v in sorted(fails.items())) or '-'} |")
    total = sum(r["success"] for r in rows)
    lines.append(f"| **all** | {pct(total / len(rows))} | | {len(rows)} | | | |")
    return "\n".join(lines)


PHASES = ("setup", "perception", "rendering", "planning", "simulation", "execution")


def phase_table(rows: list[dict]) -> str:
    """Median wall seconds per phase, per task (where a trial's time goes)."""
    lines = ["| task | " + " | ".join(PHASES) + " |", "|---|" + "---|" * len(PHASES)]
    for task in dict.fromkeys(r["task"] for r in rows):
        rs = [r["phases_s"] for r in rows if r["task"] == task and r.get("phases_s")]
        if rs:
            lines.append(f"| {task} | " + " | ".join(f"{statistics.median(p.get(k, 0.0) for p in rs):.2f} s" for k in PHASES) + " |")
    return "\n".join(lines)


def section(rows: list[dict], command: str, perception: PerceptionConfig, recovery: RecoveryPolicy,
            executor: str = "local", planner: str = "reference") -> str:
    from ..sim.tasks import TASKS
    from .published import cell_table, comparison_table

    seeds = f"; seeds {min(r['seed'] for r in rows)}–{max(r['seed'] for r in rows)}; executor: {executor}"
    predicates = "; ".join(f"{t}: {TASKS[t].predicate}" for t in dict.fromkeys(r["task"] for r in rows) if t in TASKS)
    published = comparison_table(rows) or cell_table(rows)
    return (table(rows) + ("\n\nAgainst the published figures (different planner and perception: see protocol):\n\n"
                           + published if published else "")
            + "\n\nMedian wall time per phase:\n\n" + phase_table(rows) + "\n\n"
            + footer(command, protocol(perception, recovery, planner) + seeds
                     + f"; success predicates: {predicates}; a trial also fails past the task's horizon"))


def embodiment_section(rows_by_embodiment: dict[str, list[dict]], command: str, perception: PerceptionConfig,
                       recovery: RecoveryPolicy) -> str:
    """One row per task, one column per embodiment: the same reference plan text on every robot."""
    embs = list(rows_by_embodiment)
    lines = ["| task | " + " | ".join(f"{e} success" for e in embs) + " | failures |",
             "|---|" + "---|" * len(embs) + "---|"]
    tasks = list(dict.fromkeys(r["task"] for rows in rows_by_embodiment.values() for r in rows))
    for task in tasks:
        cells, fails = [], []
        for e in embs:
            rs = [r for r in rows_by_embodiment[e] if r["task"] == task]
            k = sum(r["success"] for r in rs)
            cells.append(f"{pct(k / len(rs))} ({k}/{len(rs)})" if rs else "-")
            for r in rs:
                if not r["success"]:
                    fails.append(f"{e}: {r['failure'] or 'predicate false'}")
        counts = {f: fails.count(f) for f in dict.fromkeys(fails)}
        lines.append(f"| {task} | " + " | ".join(cells) + f" | {', '.join(f'{v}× {k}' for k, v in counts.items()) or '-'} |")
    totals = []
    for e in embs:
        rs = rows_by_embodiment[e]
        k = sum(r["success"] for r in rs)
        lo, hi = wilson(k, len(rs))
        totals.append(f"**{pct(k / len(rs))}** ({pct(lo)} – {pct(hi)})")
    lines.append("| all tasks | " + " | ".join(totals) + " | |")
    n = max(len(r) for r in rows_by_embodiment.values()) // max(len(tasks), 1)
    return "\n".join(lines) + "\n\n" + footer(
        command, protocol(perception, recovery) + f"; {n} seeds per task per embodiment; the same reference plan "
                 f"text on every embodiment (single-arm plans run on the 'right' arm); embodiments: "
                 + ", ".join(embs))


__all__ = ["run", "section", "table", "phase_table", "embodiment_section", "TrialOutcome"]
