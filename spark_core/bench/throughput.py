"""Batch throughput on this machine: the builtin suite's trials per hour on the local process pool and on Ray
(a local cluster with the same number of workers; cluster start-up counted)."""

from __future__ import annotations

import time

from ..sim.tasks import BUILTIN
from .report import footer
from .trial import PerceptionConfig


def run(trials: int = 2, workers: int = 2, resolver: str = "privileged") -> dict:
    from . import reference_suite

    out = {"trials_per_task": trials, "workers": workers, "resolver": resolver, "tasks": len(BUILTIN), "runs": {}}
    for executor in ("local", "ray"):
        t0 = time.perf_counter()
        rows = reference_suite.run(list(BUILTIN), trials, 0, workers, None, PerceptionConfig(resolver),
                                   executor=executor)
        wall = time.perf_counter() - t0
        out["runs"][executor] = {"trials": len(rows), "successes": sum(r["success"] for r in rows), "wall_s": wall,
                                 "per_hour": len(rows) / wall * 3600}
    return out


def section(r: dict, command: str) -> str:
    lines = ["| executor | trials | success | wall time | trials per hour |", "|---|---|---|---|---|"]
    for name, x in r["runs"].items():
        lines.append(f"| {name} ({r['workers']} workers) | {x['trials']} | {100 * x['successes'] / x['trials']:.1f} % | "
                     f"{x['wall_s']:.0f} s | {x['per_hour']:.0f} |")
    return "\n".join(lines) + "\n\n" + footer(
        command, f"builtin suite, {r['tasks']} tasks x {r['trials_per_task']} seeds, reference plans, resolver "
                 f"{r['resolver']}; Ray: a local cluster started by the command (start-up and shutdown included)")
