"""Health, version, grammar, tasks and plan validation."""

from __future__ import annotations

import threading
from typing import Annotated

from fastapi import APIRouter, HTTPException, Path, Response

from .models import MAX_NAME, PlanText, PlanValidation

router = APIRouter(prefix="/api", tags=["meta"])


@router.get("/health")
def health() -> dict:
    return {"status": "ok"}


@router.get("/version")
def version() -> dict:
    import mujoco

    import spark_core

    return {"spark": spark_core.__version__, "mujoco": mujoco.__version__}


@router.get("/grammar")
def grammar() -> dict:
    from spark_core import REGISTRY, plan_json_schema

    prims = [
        {
            "name": s.name,
            "tier": s.tier.value,
            "description": s.description,
            "arm": s.arm.value,
            "timeout_s": s.timeout_s,
            "postcondition": s.postcondition,
            "slots": [
                {
                    "name": x.name,
                    "type": x.type.value,
                    "required": x.required,
                    "default": x.default,
                    "unit": x.unit,
                    "min": x.minimum,
                    "max": x.maximum,
                    "values": list(x.values),
                }
                for x in s.slots
            ],
        }
        for s in REGISTRY
    ]
    return {"primitives": prims, "json_schema": plan_json_schema()}


@router.get("/catalog")
def catalog() -> dict:
    """Planners, segmenters (with their `privileged` flag), embodiments, suites, tasks, and the closed sets the
    UI interprets (verdicts, node statuses, event kinds): the one list the CLI, the API and the UI share."""
    from spark_core import catalog_json

    return catalog_json()


@router.get("/tasks")
def tasks() -> list[dict]:
    from spark_core import catalog_json

    return catalog_json()["tasks"]


@router.post("/plans/validate", response_model=PlanValidation)
def validate_plan(body: PlanText) -> PlanValidation:
    """Type-check a plan: `ok`, with the plan and its canonical YAML, or every error at its path. With
    `embodiment`, also each arm tag the robot has no arm for (and each two-arm primitive on one arm), at the node
    that says so: what POST /api/trials refuses with a 422."""
    from spark_core import plan_to_dict, to_yaml, validate

    from .arms import arm_errors

    plan, issues = validate(body.text)
    if plan is None:
        return PlanValidation(ok=False, errors=[{"path": i.path, "message": i.message} for i in issues])
    misfits = arm_errors(plan, body.embodiment) if body.embodiment is not None else []
    if misfits:
        return PlanValidation(ok=False, errors=[{"path": path, "message": message} for path, message in misfits])
    return PlanValidation(ok=True, plan=plan_to_dict(plan), canonical_yaml=to_yaml(plan))


_PREVIEWS: dict[str, bytes] = {}  # task name -> PNG of its scene (seed 0): scenes are deterministic
_PREVIEW_LOCK = threading.Lock()


@router.get("/tasks/{name}/preview.png", response_class=Response, responses={200: {"content": {"image/png": {}}}})
def task_preview(name: Annotated[str, Path(max_length=MAX_NAME)]) -> Response:
    """A picture of the task's scene at its start (seed 0, its first camera, 320 x 240), for the task card."""
    import cv2

    from spark_core import TASKS

    task = TASKS.get(name)
    if task is None:
        raise HTTPException(404, f"no task {name!r}")
    with _PREVIEW_LOCK:  # one scene built at a time (robosuite and LIBERO scenes take seconds and memory)
        if name not in _PREVIEWS:
            world = task.make_world(0)
            try:
                if world.model.ncam == 0:
                    raise HTTPException(404, f"task {name!r} has no camera to draw its scene from")
                frame = world.render(world.model.camera(0).name, 320, 240)
                ok, png = cv2.imencode(".png", cv2.cvtColor(frame.rgb, cv2.COLOR_RGB2BGR))
                _PREVIEWS[name] = png.tobytes()
            finally:
                world.close()
    return Response(_PREVIEWS[name], media_type="image/png", headers={"cache-control": "max-age=3600"})
