"""Batches: many trials from a suite (tasks × seeds) queued at once; progress, result table, cancel."""

from __future__ import annotations

import uuid

from fastapi import APIRouter, HTTPException, Request
from pydantic import BaseModel, Field

router = APIRouter(prefix="/api/batches", tags=["batches"])


class BatchCreate(BaseModel):
    suite: str = Field("builtin", description="task suite (builtin)")
    tasks: list[str] | None = Field(None, description="subset of the suite's tasks (default: all)")
    trials: int = Field(1, ge=1, le=100, description="seeds per task")
    seed: int = Field(0, ge=0)
    planner: str = Field("reference", pattern="^(reference|rules|gemini|openai)$")
    resolver: str = Field("sim", pattern="^(privileged|sim|sim-noisy)$")


@router.post("", status_code=202)
def create_batch(body: BatchCreate, request: Request) -> dict:
    from spark_core.sim.tasks import BUILTIN

    from ..runner import TrialSpec

    if body.suite != "builtin":
        raise HTTPException(422, f"unknown suite {body.suite!r}; available: builtin")
    tasks = body.tasks or list(BUILTIN)
    unknown = [t for t in tasks if t not in BUILTIN]
    if unknown:
        raise HTTPException(422, f"unknown task(s) {', '.join(unknown)}; builtin tasks: {', '.join(BUILTIN)}")
    if len(tasks) * body.trials > 2000:
        raise HTTPException(422, f"{len(tasks) * body.trials} trials is more than one batch may hold (2000)")
    batch_id = f"batch-{uuid.uuid4().hex[:10]}"
    store, runner = request.app.state.store, request.app.state.runner
    store.create_batch(batch_id, body.model_dump())
    ids = []
    for task in tasks:
        for k in range(body.trials):
            trial_id = f"{batch_id}-{task}-{body.seed + k}"
            runner.submit(trial_id, TrialSpec(task, BUILTIN[task].instruction, body.planner, body.resolver, body.seed + k),
                          batch_id=batch_id)
            ids.append(trial_id)
    return {"id": batch_id, "trials": len(ids)}


@router.get("/{batch_id}")
def get_batch(batch_id: str, request: Request) -> dict:
    from spark_core.bench.report import wilson

    batch = request.app.state.store.get_batch(batch_id)
    if batch is None:
        raise HTTPException(404, f"no batch {batch_id!r}")
    trials = batch["trials"]
    done = [t for t in trials if t["status"] in ("done", "interrupted")]
    table = []
    for task in dict.fromkeys(t["task"] for t in trials):
        rs = [t for t in done if t["task"] == task]
        k = sum(bool(t["success"]) for t in rs)
        lo, hi = wilson(k, len(rs))
        table.append({"task": task, "done": len(rs), "total": sum(t["task"] == task for t in trials), "successes": k,
                      "success_rate": k / len(rs) if rs else None, "ci95": [lo, hi]})
    status = batch["status"] if batch["status"] == "cancelled" or len(done) < len(trials) else "done"
    return {**batch, "status": status, "progress": {"done": len(done), "total": len(trials)}, "results": table}


@router.post("/{batch_id}/cancel")
def cancel_batch(batch_id: str, request: Request) -> dict:
    store, runner = request.app.state.store, request.app.state.runner
    batch = store.get_batch(batch_id)
    if batch is None:
        raise HTTPException(404, f"no batch {batch_id!r}")
    cancelled = sum(runner.cancel(t["id"]) for t in batch["trials"] if t["status"] in ("queued", "running"))
    store.set_batch_status(batch_id, "cancelled")
    return {"id": batch_id, "cancelled": cancelled}
