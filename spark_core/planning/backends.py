"""Planner backends by name (CLI flags and config select them here)."""

from __future__ import annotations

from .protocol import Planner

BACKENDS = ("rules", "gemini", "openai")


def make_planner(name: str, model: str | None = None, base_url: str | None = None) -> Planner:
    """Raises llm.PlannerUnavailable with what is missing (key, server) when a backend cannot run."""
    if name == "rules":
        from .rules import RulesPlanner

        return RulesPlanner()
    if name == "gemini":
        from .gemini import DEFAULT_MODEL, GeminiPlanner

        return GeminiPlanner(model or DEFAULT_MODEL, base_url=base_url)
    if name == "openai":
        from .openai_compat import OpenAIPlanner

        if not model:
            raise ValueError("the openai planner needs --model (e.g. gpt-4.1, or the name your local server serves)")
        return OpenAIPlanner(model, base_url=base_url)
    raise ValueError(f"unknown planner {name!r}; available: {', '.join(BACKENDS)}")
