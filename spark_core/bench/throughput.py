"""Batch throughput on this machine: trials per hour per suite on the local process pool and on Ray (a local
cluster with the same number of workers; cluster start-up counted)."""

from __future__ import annotations

import time
from typing import Any

from .report import footer

PLANNER = {"builtin": "reference", "capbench": "reference", "liberopro": "rules"}  # liberopro has no reference plans


def tasks_of(suite: str) -> list[str]:
    """The suite's tasks; for liberopro the first task of each of its six cells (a throughput sample)."""
    from ..sim.tasks import SUITES

    names = list(SUITES[suite])
    if suite == "liberopro":
        return [
            next(n for n in names if n.startswith(cell + ":")) for cell in dict.fromkeys(n.split(":")[0] for n in names)
        ]
    return names


def run(
    trials: int = 2, workers: int = 2, segmenter: str = "privileged-keypoints", suites: tuple[str, ...] = ("builtin",)
) -> dict:
    from ..trial import TrialConfig
    from . import manifest, reference_suite

    out: dict[str, Any] = {"trials_per_task": trials, "workers": workers, "segmenter": segmenter, "suites": {}}
    for suite in suites:
        tasks = tasks_of(suite)
        runs = {}
        template = TrialConfig("", planner=PLANNER.get(suite, "reference"), segmenter=segmenter)
        # one manifest per suite: both executors run the same tasks x seeds with the same settings
        m = manifest.build(
            suite=suite, tasks=tasks, seeds=range(trials), template=template, executor="local and ray", workers=workers
        )
        for executor in ("local", "ray"):
            t0 = time.perf_counter()
            rows = reference_suite.run(tasks, trials, 0, workers, None, template, executor=executor)
            wall = time.perf_counter() - t0
            runs[executor] = {
                "trials": len(rows),
                "successes": sum(r["success"] for r in rows),
                "wall_s": wall,
                "per_hour": len(rows) / wall * 3600,
                "trial_phases_s": _median_phases(rows),
            }
        out["suites"][suite] = {
            "tasks": len(tasks),
            "planner": PLANNER.get(suite, "reference"),
            "runs": runs,
            "manifest": {"id": m["id"], "git": m["environment"]["git"], "files": len(m["files"])},
        }
    return out


PHASES = ("setup", "perception", "rendering", "planning", "simulation")
PROFILE_DOC = "docs/profiles/liberopro_trial.md"  # the profile before and after the throughput work


def _median_phases(rows: list[dict]) -> dict[str, float]:
    """Median wall seconds per trial: the whole trial and each phase the pipeline times (TrialOutcome.phases_s)."""
    import statistics

    out = {"trial": statistics.median(r["wall_time_s"] for r in rows)} if rows else {}
    for phase in PHASES:
        values = [r["phases_s"][phase] for r in rows if phase in (r.get("phases_s") or {})]
        if values:
            out[phase] = statistics.median(values)
    return out


def section(r: dict, command: str) -> str:
    from ..catalog import SEGMENTERS

    privileged = "PRIVILEGED" if SEGMENTERS[r["segmenter"]].privileged else "non-privileged"
    lines = ["| suite | executor | trials | success | wall time | trials per hour |", "|---|---|---|---|---|---|"]
    for suite, s in r["suites"].items():
        for name, x in s["runs"].items():
            lines.append(
                f"| {suite} | {name} ({r['workers']} workers) | {x['trials']} | "
                f"{100 * x['successes'] / x['trials']:.1f} % | {x['wall_s']:.0f} s | {x['per_hour']:.0f} |"
            )
    phases = [
        f"| {suite} | {name} | "
        + " | ".join(f"{x['trial_phases_s'][k]:.2f} s" if k in x["trial_phases_s"] else "-" for k in ("trial", *PHASES))
        + " |"
        for suite, s in r["suites"].items()
        for name, x in s["runs"].items()
        if x.get("trial_phases_s")
    ]
    if phases:
        lines += [
            "",
            "Median wall time per trial and per phase (planning includes the perception and rendering it asks for):",
            "",
            "| suite | executor | trial | " + " | ".join(PHASES) + " |",
            "|---" * (3 + len(PHASES)) + "|",
            *phases,
        ]
    what = "; ".join(
        f"{suite}: {s['tasks']} tasks x {r['trials_per_task']} seeds, planner {s['planner']}"
        + (" (one task per cell)" if suite == "liberopro" else "")
        for suite, s in r["suites"].items()
    )
    return (
        "\n".join(lines)
        + "\n\n"
        + footer(
            command,
            f"{what}; segmenter {r['segmenter']} ({privileged}); wording: each task's own instruction (official); "
            "seeds 0 and up; Ray: a local cluster started by the command (start-up and shutdown included); a "
            "worker process reuses a LIBERO env across consecutive trials of the same task (reset to the trial's "
            "init state: the same start state as a fresh env, tests/bench/test_env_reuse.py), other scenes are "
            "built afresh; robosuite/LIBERO camera frames draw their RGB only when it is read (the same pixels; the "
            f"sim segmenter reads depth and ids only); where a LIBERO-PRO trial's time goes, before and after: "
            f"[{PROFILE_DOC}]({PROFILE_DOC}); run manifests: "
            + ", ".join(f"{suite} `{s['manifest']['id']}`" for suite, s in r["suites"].items() if "manifest" in s),
        )
    )
