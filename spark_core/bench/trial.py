"""Run one task trial: build the world from a seed, run a plan through the executor, evaluate success."""

from __future__ import annotations

import time
from dataclasses import dataclass, field
from typing import Any

from ..execution import Executor, RecoveryPolicy, TrialResult
from ..execution.primitives import PrimitiveLibrary
from ..grammar import Plan, parse_plan
from ..perception.privileged import PrivilegedResolver
from ..sim.tasks import TaskSpec


@dataclass
class TrialOutcome:
    task: str
    seed: int
    success: bool
    outcome: str
    failure: str | None
    failed_node: str | None
    reason: str
    sim_time_s: float
    wall_time_s: float
    protocol: dict[str, str]
    result: TrialResult | None = field(default=None, repr=False)

    def row(self) -> dict[str, Any]:
        return {k: v for k, v in self.__dict__.items() if k != "result"}


def run_reference_trial(task: TaskSpec, seed: int, plan: Plan | None = None,
                        recovery: RecoveryPolicy = RecoveryPolicy()) -> TrialOutcome:
    """The task's hand-written reference plan (or `plan`) with the PRIVILEGED resolver: tests control alone."""
    t0 = time.perf_counter()
    world = task.make_world(seed)
    try:
        resolver = PrivilegedResolver(world)
        library = PrimitiveLibrary(world, resolver, seed=seed)
        plan = plan or parse_plan(task.reference_plan_text())
        result = Executor(library, resolver, recovery=recovery, trial_id=f"{task.name}-{seed}").run(plan)
        world.settle(0.5)
        success = bool(task.success(world))
    finally:
        world.close()
    return TrialOutcome(
        task=task.name, seed=seed, success=success, outcome=result.outcome,
        failure=result.failure.value if result.failure else None, failed_node=result.failed_node, reason=result.reason,
        sim_time_s=round(world.sim_time_s, 3), wall_time_s=round(time.perf_counter() - t0, 3),
        protocol={"planner": "reference plan (hand-written)", "resolver": PrivilegedResolver.__name__ + " (privileged:sim-state)"},
        result=result,
    )
