"""User configuration: `spark.yaml` in the working directory, or the file named by SPARK_CONFIG.

Keys (all optional): planner, model, base_url, segmenter (catalog names: `spark catalog`), plan_library ('store'
or a .jsonl path), prices ({model: [input_usd_per_mtok, output_usd_per_mtok]}), endpoints (the LLM endpoints API
callers may choose by name, with the environment variable of each one's key: planning/endpoints.py).
Command-line flags win.
"""

from __future__ import annotations

import os
from dataclasses import dataclass, field
from pathlib import Path

import yaml

from .planning.endpoints import Endpoint, parse_endpoints

KEYS = ("planner", "model", "base_url", "segmenter", "plan_library", "prices", "endpoints")


@dataclass(frozen=True)
class Config:
    planner: str | None = None
    model: str | None = None
    base_url: str | None = None
    segmenter: str | None = None
    plan_library: str | None = None
    prices: dict[str, tuple[float, float]] = field(default_factory=dict)
    endpoints: dict[str, Endpoint] = field(default_factory=dict)
    source: str = ""


def load_config(path: str | os.PathLike | None = None) -> Config:
    """Read the config; a missing default file is an empty config, a broken one is an error naming the key."""
    explicit = path or os.environ.get("SPARK_CONFIG")
    p = Path(explicit) if explicit else Path("spark.yaml")
    if not p.exists():
        if explicit:
            raise FileNotFoundError(f"config file {p} does not exist")
        return Config()
    data = yaml.safe_load(p.read_text()) or {}
    if not isinstance(data, dict):
        raise ValueError(f"{p}: expected a mapping of settings, got {type(data).__name__}")
    unknown = sorted(set(data) - set(KEYS))
    if unknown:
        raise ValueError(f"{p}: unknown setting(s) {', '.join(unknown)}; known: {', '.join(KEYS)}")
    prices = {}
    for model, rate in (data.get("prices") or {}).items():
        if not (isinstance(rate, (list, tuple)) and len(rate) == 2 and all(isinstance(x, (int, float)) for x in rate)):
            raise ValueError(f"{p}: prices.{model}: expected [input_usd_per_mtok, output_usd_per_mtok], got {rate!r}")
        prices[str(model)] = (float(rate[0]), float(rate[1]))
    return Config(
        **{k: data.get(k) for k in KEYS if k not in ("prices", "endpoints")},
        prices=prices,
        endpoints=parse_endpoints(data.get("endpoints"), str(p)),
        source=str(p),
    )
