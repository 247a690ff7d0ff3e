"""A suite of trials through the one trial pipeline (`spark_core.trial.run_trial`), on the local process pool or
Ray, with Markdown reports. Reference plans measure control and primitives; planners measure the whole loop."""

from __future__ import annotations

import statistics
from collections.abc import Callable, Iterable
from dataclasses import replace

from ..trial import TrialConfig, TrialOutcome, run_trial
from .report import footer, pct, wilson


def protocol(config: TrialConfig) -> str:
    """A suite's protocol in words, from its trial template (planner, segmenter and whether it is privileged,
    cameras, adaptive prompts, recovery, success rule)."""
    p = config.protocol(0.0)
    seg = f"{p['segmenter']} ({'PRIVILEGED' if p['privileged'] else 'non-privileged'}: {p['segmenter_description']})"
    if p["cameras"] != "none":
        seg += (
            f", cameras {p['cameras']} 640x480, "
            f"adaptive prompts {'on (label + 3 variants)' if p['adaptive_prompts'] else 'off'}"
        )
    if p["noise"]:
        seg += f", noise: {p['noise']}, misses independent per prompt and per view"
    rec = "recovery tiers 1-2 on (2 retries per node), replan off" if config.recovery else "recovery off"
    return (
        f"planner: {p['planner']}; wording: {p['wording']}; segmenter: {seg}; {rec}; "
        f"success: {p['success_rule']} (the task's own time limit)"
    )


def _one(job: tuple[TrialConfig, str | None, str, str | None]) -> dict:
    config, store_url, trial_id, library_path = job
    library = None
    if library_path:
        from ..planning.plan_library import PlanLibrary

        library = PlanLibrary(library_path, read_only=True)  # every trial sees the same examples
    sinks = []
    if store_url:
        from ..trace import TraceStore
        from ..trace.sink import StoreSink

        sinks.append(StoreSink(TraceStore(store_url, migrate=False)))  # the driver migrated it
    return run_trial(config, sinks, trial_id=trial_id, library=library).row()


def run(
    tasks: Iterable[str],
    trials: int,
    seed: int = 0,
    workers: int = 1,
    progress: Callable[[dict], None] | None = None,
    template: TrialConfig | None = None,
    executor: str = "local",
    ray_address: str | None = None,
    store_url: str | None = None,
    batch_id: str | None = None,
    manifest: dict | None = None,
    plan_library: str | None = None,
) -> list[dict]:
    """Every task x seed with `template`'s settings; `executor` local (process pool of `workers`) or ray (see
    bench.executors). With `store_url` every trial is recorded in that trace store under one batch (`batch_id`,
    default a new one; its spec keeps `manifest`, see bench.manifest). `plan_library`: a JSON-lines plan library
    whose examples LLM planners get, read-only for the run."""
    import uuid

    from .executors import run_jobs

    template = template or TrialConfig(task="", segmenter="privileged-keypoints")
    tasks = list(tasks)
    batch_id = batch_id or f"bench-{uuid.uuid4().hex[:10]}"
    configs = [replace(template, task=t, seed=seed + k).check() for t in tasks for k in range(trials)]
    if store_url:
        from ..trace import TraceStore

        TraceStore(store_url).create_batch(
            batch_id,
            {
                "suite": "bench",
                "tasks": tasks,
                "trials": trials,
                "seed": seed,
                "segmenter": template.segmenter,
                "planner": template.planner,
                "executor": executor,
                **({"manifest": manifest} if manifest else {}),
            },
        )
        configs = [replace(c, batch_id=batch_id) for c in configs]
    # Ids decided before submission: a trial retried after its worker died writes the same record again
    jobs = [(c, store_url, f"{batch_id}-{i:04d}-s{c.seed}", plan_library) for i, c in enumerate(configs)]
    return run_jobs(_one, jobs, executor, workers, ray_address, progress)


def table(rows: list[dict]) -> str:
    lines = [
        "| task | success | 95 % CI | trials | median sim time | median wall time | failures |",
        "|---|---|---|---|---|---|---|",
    ]
    for task in dict.fromkeys(r["task"] for r in rows):
        rs = [r for r in rows if r["task"] == task]
        k = sum(r["success"] for r in rs)
        lo, hi = wilson(k, len(rs))
        fails: dict[str, int] = {}
        for r in rs:
            if not r["success"]:
                key = r["verdict"] + (f" ({r['failure']})" if r["failure"] and r["verdict"] == "tree_failed" else "")
                fails[key] = fails.get(key, 0) + 1
        lines.append(
            f"| {task} | {pct(k / len(rs))} | {pct(lo)} – {pct(hi)} | {len(rs)} | "
            f"{statistics.median(r['sim_time_s'] for r in rs):.1f} s | "
            f"{statistics.median(r['wall_time_s'] for r in rs):.2f} s | "
            f"{', '.join(f'{v}× {k}' for k, v in sorted(fails.items())) or '-'} |"
        )
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
            lines.append(
                f"| {task} | "
                + " | ".join(f"{statistics.median(p.get(k, 0.0) for p in rs):.2f} s" for k in PHASES)
                + " |"
            )
    return "\n".join(lines)


def section(rows: list[dict], command: str, template: TrialConfig, executor: str = "local") -> str:
    from ..sim.tasks import TASKS
    from .published import cell_table, comparison_table

    seeds = f"; seeds {min(r['seed'] for r in rows)}–{max(r['seed'] for r in rows)}; executor: {executor}"
    predicates = "; ".join(f"{t}: {TASKS[t].predicate}" for t in dict.fromkeys(r["task"] for r in rows) if t in TASKS)
    published = comparison_table(rows) or cell_table(rows)
    return (
        table(rows)
        + (
            "\n\nAgainst the published figures (different planner and perception: see protocol):\n\n" + published
            if published
            else ""
        )
        + "\n\nMedian wall time per phase:\n\n"
        + phase_table(rows)
        + "\n\n"
        + footer(command, protocol(template) + seeds + f"; success predicates: {predicates}")
    )


def embodiment_section(rows_by_embodiment: dict[str, list[dict]], command: str, template: TrialConfig) -> str:
    """One row per task, one column per embodiment: the same reference plan text on every robot."""
    embs = list(rows_by_embodiment)
    lines = [
        "| task | " + " | ".join(f"{e} success" for e in embs) + " | failures |",
        "|---|" + "---|" * len(embs) + "---|",
    ]
    tasks = list(dict.fromkeys(r["task"] for rows in rows_by_embodiment.values() for r in rows))
    for task in tasks:
        cells, fails = [], []
        for e in embs:
            rs = [r for r in rows_by_embodiment[e] if r["task"] == task]
            k = sum(r["success"] for r in rs)
            cells.append(f"{pct(k / len(rs))} ({k}/{len(rs)})" if rs else "-")
            for r in rs:
                if not r["success"]:
                    fails.append(f"{e}: {r['verdict']}" + (f" ({r['failure']})" if r["failure"] else ""))
        counts = {f: fails.count(f) for f in dict.fromkeys(fails)}
        lines.append(
            f"| {task} | " + " | ".join(cells) + f" | {', '.join(f'{v}× {k}' for k, v in counts.items()) or '-'} |"
        )
    totals = []
    for e in embs:
        rs = rows_by_embodiment[e]
        k = sum(r["success"] for r in rs)
        lo, hi = wilson(k, len(rs))
        totals.append(f"**{pct(k / len(rs))}** ({pct(lo)} – {pct(hi)})")
    lines.append("| all tasks | " + " | ".join(totals) + " | |")
    n = max(len(r) for r in rows_by_embodiment.values()) // max(len(tasks), 1)
    return (
        "\n".join(lines)
        + "\n\n"
        + footer(
            command,
            protocol(template) + f"; {n} seeds per task per embodiment; the same reference plan "
            f"text on every embodiment (single-arm plans run on the 'right' arm); embodiments: " + ", ".join(embs),
        )
    )


__all__ = ["run", "section", "table", "phase_table", "embodiment_section", "TrialOutcome"]
