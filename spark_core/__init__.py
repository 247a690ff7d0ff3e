"""SPARK engine: typed behavior-tree grammar, perception, planning, control, simulation and execution.

Importable without the server. This module is the engine's public API: `server/` imports only names listed
here (a test checks it). Names load lazily, so `import spark_core` stays cheap (no MuJoCo until used).
"""

from __future__ import annotations

import importlib
from typing import Any

__version__ = "0.1.0"

# public name -> module that defines it
_EXPORTS: dict[str, str] = {
    # the trial pipeline
    "TrialConfig": "spark_core.trial",
    "TrialConfigError": "spark_core.trial",
    "run_trial": "spark_core.trial",
    "TrialSink": "spark_core.trial",
    "BaseSink": "spark_core.trial",
    "TrialContext": "spark_core.trial",
    "TrialOutcome": "spark_core.trial_outcome",
    "Verdict": "spark_core.trial_outcome",
    "config_record": "spark_core.trial_record",
    "config_from_record": "spark_core.trial_record",
    # the catalog
    "catalog_json": "spark_core.catalog",
    "CatalogError": "spark_core.catalog",
    "PLANNERS": "spark_core.catalog",
    "SEGMENTERS": "spark_core.catalog",
    "DEFAULT_SEGMENTER": "spark_core.catalog",
    "EMBODIMENTS": "spark_core.catalog",
    "ALL_EMBODIMENTS": "spark_core.catalog",
    "BENCHMARK_EMBODIMENTS": "spark_core.catalog",
    "check_task": "spark_core.catalog",
    "suites": "spark_core.catalog",
    "task_entry": "spark_core.catalog",
    "check_planner": "spark_core.catalog",
    "check_segmenter": "spark_core.catalog",
    "check_embodiment": "spark_core.catalog",
    "enums": "spark_core.catalog",
    # execution: control and the closed sets
    "StepControl": "spark_core.execution",
    "Aborted": "spark_core.execution",
    "EventKind": "spark_core.execution",
    "NodeStatus": "spark_core.execution",
    "TreeStatus": "spark_core.execution",
    # grammar
    "REGISTRY": "spark_core.grammar",
    "plan_json_schema": "spark_core.grammar",
    "plan_to_dict": "spark_core.grammar",
    "to_yaml": "spark_core.grammar",
    "validate": "spark_core.grammar",
    # perception (drawing)
    "Keypoint": "spark_core.perception",
    "annotate": "spark_core.perception.annotate",
    "LearnedSegmenter": "spark_core.perception.learned.segmenter",
    # simulation (scenes for the 3D view)
    "TASKS": "spark_core.sim.tasks",
    "CaptureConfig": "spark_core.sim.capture",
    "body_poses": "spark_core.sim.geometry",
    "visual_geoms": "spark_core.sim.geometry",
    "VisualGeom": "spark_core.sim.geometry",
    # trace store, its sink, exports
    "TraceStore": "spark_core.trace",
    "StoreLease": "spark_core.trace.lease",
    "LeaseHeld": "spark_core.trace.lease",
    "StoreSink": "spark_core.trace.sink",
    "StorePlanLibrary": "spark_core.trace.library_table",
    "export_lerobot": "spark_core.trace.lerobot",
    "ExportError": "spark_core.trace.lerobot",
    "ExportFilter": "spark_core.trace.lerobot",
    # reports
    "wilson": "spark_core.bench.report",
    "batch_manifest": "spark_core.bench.manifest",
    "PROTOCOLS": "spark_core.bench.protocols",
    "ProtocolError": "spark_core.bench.protocols",
    "apply_protocol": "spark_core.bench.protocols",
}


def warm_up() -> None:
    """Import the simulator, perception and planners and load the text encoder, so a worker's first trial does
    not pay for it."""
    from .perception.text_encoder import SHARED_ENCODER
    from .sim.tasks import TASKS  # noqa: F401 - mujoco, robot models, every suite
    from .trial import run_trial  # noqa: F401 - perception, primitives, executor

    SHARED_ENCODER.encode(["warm up"])


def __getattr__(name: str) -> Any:
    module = _EXPORTS.get(name)
    if module is None:
        raise AttributeError(f"module 'spark_core' has no attribute {name!r}")
    value = getattr(importlib.import_module(module), name)
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted([*globals(), *_EXPORTS])


__all__ = ["__version__", "warm_up", *_EXPORTS]
