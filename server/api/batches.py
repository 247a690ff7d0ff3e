"""Batches: many trials queued at once, from a suite (tasks × seeds) or an explicit list of trial specs;
progress, result table (JSON or CSV), per-trial export, cancel."""

from __future__ import annotations

import uuid

from fastapi import APIRouter, HTTPException, Request
from fastapi.responses import PlainTextResponse
from pydantic import BaseModel, Field

router = APIRouter(prefix="/api/batches", tags=["batches"])


class BatchTrial(BaseModel):
    """One trial of an explicit batch; unset fields take the batch's values."""

    task: str
    instruction: str | None = Field(None, max_length=2000, description="default: the task's own")
    seed: int = Field(0, ge=0)
    planner: str | None = Field(None, pattern="^(reference|rules|gemini|openai)$")
    resolver: str | None = Field(None, pattern="^(privileged|sim|sim-noisy)$")


class BatchCreate(BaseModel):
    suite: str = Field("builtin", description="task suite (builtin, bimanual)")
    specs: list[BatchTrial] | None = Field(None, max_length=2000,
                                           description="explicit trials (instead of tasks × trials from the suite)")
    tasks: list[str] | None = Field(None, description="subset of the suite's tasks (default: all)")
    trials: int = Field(1, ge=1, le=100, description="seeds per task")
    seed: int = Field(0, ge=0)
    planner: str = Field("reference", pattern="^(reference|rules|gemini|openai)$")
    resolver: str = Field("sim", pattern="^(privileged|sim|sim-noisy)$")
    capture: bool = Field(False, description="record training-data frames for every trial (for LeRobot export)")


@router.post("", status_code=202)
def create_batch(body: BatchCreate, request: Request) -> dict:
    from spark_core.sim.tasks import SUITES, TASKS

    from ..runner import TrialSpec

    if body.suite not in SUITES:
        raise HTTPException(422, f"unknown suite {body.suite!r}; available: {', '.join(SUITES)}")
    # named tasks may come from any suite; without names, the whole chosen suite runs
    pool = TASKS if (body.tasks or body.specs) else SUITES[body.suite]
    if body.specs is not None:
        if not body.specs:
            raise HTTPException(422, "specs is empty: give at least one trial, or leave it out to run the suite")
        wanted = [sp.task for sp in body.specs]
    else:
        wanted = body.tasks or list(pool)
    unknown = [t for t in dict.fromkeys(wanted) if t not in pool]
    if unknown:
        raise HTTPException(422, f"unknown task(s) {', '.join(unknown)}; {body.suite} tasks: {', '.join(pool)}")
    no_plan = [t for t in dict.fromkeys(wanted) if not pool[t].has_reference_plan]
    planners = [sp.planner or body.planner for sp in body.specs] if body.specs is not None else [body.planner]
    if no_plan and "reference" in planners:
        raise HTTPException(422, f"task(s) {', '.join(no_plan[:5])}{' ...' if len(no_plan) > 5 else ''} have no "
                                 "reference plan: choose a planner (rules, gemini, openai)")
    if body.specs is not None:
        specs = [TrialSpec(sp.task, sp.instruction or pool[sp.task].instruction, sp.planner or body.planner,
                           sp.resolver or body.resolver, sp.seed, capture=body.capture) for sp in body.specs]
    else:
        specs = [TrialSpec(task, pool[task].instruction, body.planner, body.resolver, body.seed + k,
                           capture=body.capture) for task in wanted for k in range(body.trials)]
    if len(specs) > 2000:
        raise HTTPException(422, f"{len(specs)} trials is more than one batch may hold (2000)")
    batch_id = f"batch-{uuid.uuid4().hex[:10]}"
    store, runner = request.app.state.store, request.app.state.runner
    store.create_batch(batch_id, body.model_dump())
    ids = []
    for n, spec in enumerate(specs):
        trial_id = f"{batch_id}-{n:04d}-{spec.task}-{spec.seed}"
        runner.submit(trial_id, spec, batch_id=batch_id)
        ids.append(trial_id)
    return {"id": batch_id, "trials": len(ids)}


@router.get("/{batch_id}")
def get_batch(batch_id: str, request: Request) -> dict:
    return _batch_with_results(request, batch_id)


CSV_TRIAL_COLUMNS = ("id", "task", "seed", "instruction", "planner", "resolver", "status", "outcome", "success",
                     "failure", "failed_node", "reason", "wall_time_s", "sim_time_s", "cost_usd")


@router.get("/{batch_id}/results.csv", response_class=PlainTextResponse)
def batch_results_csv(batch_id: str, request: Request) -> PlainTextResponse:
    """The per-task result table (success rate with its Wilson 95 % interval) as CSV."""
    b = _batch_with_results(request, batch_id)
    rows = [{"task": r["task"], "done": r["done"], "total": r["total"], "successes": r["successes"],
             "success_rate": r["success_rate"], "ci95_low": r["ci95"][0], "ci95_high": r["ci95"][1]} for r in b["results"]]
    return _csv(rows, ("task", "done", "total", "successes", "success_rate", "ci95_low", "ci95_high"), f"{batch_id}-results.csv")


@router.get("/{batch_id}/trials.csv", response_class=PlainTextResponse)
def batch_trials_csv(batch_id: str, request: Request) -> PlainTextResponse:
    """One row per trial of the batch (outcome, failure attribution, timings, cost) as CSV."""
    b = _batch_with_results(request, batch_id)
    return _csv(b["trials"], CSV_TRIAL_COLUMNS, f"{batch_id}-trials.csv")


def _csv(rows: list[dict], columns: tuple[str, ...], filename: str) -> PlainTextResponse:
    import csv
    import io

    buf = io.StringIO()
    w = csv.DictWriter(buf, fieldnames=columns, extrasaction="ignore", lineterminator="\n")
    w.writeheader()
    w.writerows(rows)
    return PlainTextResponse(buf.getvalue(), media_type="text/csv",
                             headers={"content-disposition": f'attachment; filename="{filename}"'})


def _batch_with_results(request: Request, batch_id: str) -> dict:
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
