"""Recovery tiers: which one to try on which retry of a failed node."""

from __future__ import annotations

from dataclasses import dataclass

from ..grammar import PrimitiveSpec
from .protocols import FailureKind

PERTURB = 1  # in-place perturbation (wiggle / grasp_perturb) for contact primitives
REDETECT = 2  # retract along +z, re-detect, re-resolve labels, retry the same node
REPLAN = 3  # ask the planner for a new tree (off by default)


@dataclass(frozen=True)
class RecoveryPolicy:
    max_retries: int = 2  # per node; then the node fails closed
    perturb: bool = True
    redetect: bool = True
    replan: bool = False
    max_replans: int = 1  # per trial
    retract_m: float = 0.10

    def tier_for(self, spec: PrimitiveSpec, retry: int, failure: FailureKind | None) -> int | None:
        """Tier for the `retry`-th retry (1-based) of a node that failed with `failure`; None = give up."""
        if retry > self.max_retries or failure is FailureKind.PLANNER:
            return None
        can_perturb = self.perturb and spec.perturbation is not None and failure is FailureKind.CONTROL
        if retry == 1 and can_perturb:
            return PERTURB
        if self.redetect:
            return REDETECT
        return PERTURB if can_perturb else None
