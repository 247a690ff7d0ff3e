"""Planner backends by name (CLI flags and config select them here)."""

from __future__ import annotations

from .protocol import Planner

BACKENDS = ("rules",)


def make_planner(name: str) -> Planner:
    if name == "rules":
        from .rules import RulesPlanner

        return RulesPlanner()
    raise ValueError(f"unknown planner {name!r}; available: {', '.join(BACKENDS)}")
