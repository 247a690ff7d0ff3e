"""Planner backends by name (the catalog's planners; CLI flags, config and the API select them here)."""

from __future__ import annotations

from .llm import PlannerUnavailable
from .protocol import Planner


def make_planner(
    name: str, model: str | None = None, base_url: str | None = None, endpoint: str | None = None
) -> Planner:
    """Raises PlannerUnavailable (what is missing: a key, a server) or ValueError (a bad choice).

    Keys: a named `endpoint` (the operator's allowlist) gets the key of its `api_key_env`; the vendor's own URL
    gets the usual environment key; any other `base_url` gets no key at all (a local server), so a URL someone
    else chose never receives the server's credentials."""
    if name == "rules":
        from .rules import RulesPlanner

        return RulesPlanner()
    api_key = None
    if endpoint is not None:
        from .endpoints import resolve_endpoint

        ep = resolve_endpoint(endpoint, name, model)
        base_url, api_key = ep.base_url, ep.api_key()
        if ep.api_key_env and not api_key:
            raise PlannerUnavailable(f"endpoint {endpoint!r} needs its key: set {ep.api_key_env} on the server")
        if name == "gemini" and not api_key:  # the Gemini API takes no request without a key
            raise PlannerUnavailable(
                f"endpoint {endpoint!r} has no key: a gemini endpoint needs api_key_env (spark.yaml)"
            )
    shown_as = f"endpoint {endpoint!r}" if endpoint is not None else None  # never the operator's URL
    if name == "gemini":
        from .gemini import DEFAULT_MODEL, GeminiPlanner

        return GeminiPlanner(model or DEFAULT_MODEL, api_key=api_key, base_url=base_url)
    if name == "openai":
        from .openai_compat import OpenAIPlanner

        if not model:
            raise ValueError("the openai planner needs --model (e.g. gpt-4.1, or the name your local server serves)")
        return OpenAIPlanner(model, base_url=base_url, api_key=api_key, shown_as=shown_as)
    raise ValueError(f"unknown planner {name!r}")
