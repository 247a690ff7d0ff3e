"""LLM endpoints are the operator's configuration: a named allowlist (spark.yaml `endpoints:`), each with the
environment variable that holds its key. Callers choose an endpoint by name; a URL that is not on the list
never receives a key from the server's environment.

    endpoints:
      local-qwen: {planner: openai, base_url: "http://127.0.0.1:11434/v1", models: [qwen3-vl]}
      gemini-proxy: {planner: gemini, base_url: "https://proxy.example/gemini", api_key_env: PROXY_KEY}
"""

from __future__ import annotations

import os
from dataclasses import dataclass
from typing import Any

LLM_PLANNERS = ("gemini", "openai")


@dataclass(frozen=True)
class Endpoint:
    name: str
    planner: str  # gemini | openai
    base_url: str | None = None  # None: the vendor's own
    api_key_env: str | None = None  # the environment variable holding its key; None: no key (local servers)
    models: tuple[str, ...] = ()  # models callers may pick (empty: any)

    def api_key(self) -> str | None:
        return os.environ.get(self.api_key_env) if self.api_key_env else None

    def public(self) -> dict[str, Any]:
        """What callers may see: never the key, nor the URL the operator chose."""
        return {"name": self.name, "planner": self.planner, "models": list(self.models)}


def parse_endpoints(data: Any, source: str) -> dict[str, Endpoint]:
    """The `endpoints:` mapping of a config file, checked; errors name the entry and the field."""
    if data is None:
        return {}
    if not isinstance(data, dict):
        raise ValueError(f"{source}: endpoints: expected a mapping of name -> settings, got {type(data).__name__}")
    out = {}
    for name, entry in data.items():
        where = f"{source}: endpoints.{name}"
        if not isinstance(entry, dict):
            raise ValueError(f"{where}: expected a mapping, got {type(entry).__name__}")
        unknown = sorted(set(entry) - {"planner", "base_url", "api_key_env", "models"})
        if unknown:
            raise ValueError(
                f"{where}: unknown field(s) {', '.join(unknown)}; known: planner, base_url, api_key_env, models"
            )
        if entry.get("planner") not in LLM_PLANNERS:
            raise ValueError(
                f"{where}.planner: expected one of {', '.join(LLM_PLANNERS)}, got {entry.get('planner')!r}"
            )
        models = entry.get("models") or []
        if not isinstance(models, list) or not all(isinstance(m, str) for m in models):
            raise ValueError(f"{where}.models: expected a list of model names")
        out[str(name)] = Endpoint(
            str(name), entry["planner"], entry.get("base_url"), entry.get("api_key_env"), tuple(models)
        )
    return out


def configured_endpoints() -> dict[str, Endpoint]:
    from ..config import load_config

    return load_config().endpoints


def resolve_endpoint(name: str, planner: str, model: str | None) -> Endpoint:
    """The configured endpoint `name`, checked against the planner and model a caller asked for."""
    endpoints = configured_endpoints()
    ep = endpoints.get(name)
    if ep is None:
        known = ", ".join(endpoints) or "none is configured (spark.yaml endpoints:)"
        raise ValueError(f"endpoint: unknown endpoint {name!r}; configured: {known}")
    if ep.planner != planner:
        raise ValueError(f"endpoint: {name!r} serves the {ep.planner} planner, not {planner!r}")
    if ep.models and model is None:  # the planner's default model is not one the operator allowed here
        raise ValueError(f"model: endpoint {name!r} serves only {', '.join(ep.models)}: name one of them")
    if ep.models and model is not None and model not in ep.models:
        raise ValueError(f"model: endpoint {name!r} serves {', '.join(ep.models)}, not {model!r}")
    return ep
