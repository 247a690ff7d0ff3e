"""Batches: many trials queued at once, from a suite (tasks × seeds) or an explicit list of trial specs;
progress, result table (JSON or CSV), per-trial export, cancel."""

from __future__ import annotations

import uuid
from collections import Counter
from typing import Annotated

from fastapi import APIRouter, HTTPException, Path, Query, Request
from fastapi.responses import PlainTextResponse
from pydantic import BaseModel, ConfigDict, Field, ValidationError

from spark_core import DEFAULT_SEGMENTER, PLANNERS, PROTOCOLS, SEGMENTERS, StorePlanLibrary, batch_manifest, wilson
from spark_core import suites as catalog_suites

from ..validation import safe_errors
from .models import MAX_ID, MAX_NAME, MAX_OFFSET, MAX_SEED, MODEL_NAME, TrialCreate
from .text import VISIBLE, Visible
from .trials import trial_config

router = APIRouter(prefix="/api/batches", tags=["batches"])
BatchId = Annotated[str, Path(max_length=MAX_ID)]


class BatchTrial(BaseModel):
    """One trial of an explicit batch; unset fields take the batch's values."""

    model_config = ConfigDict(extra="forbid")

    task: Visible = Field(max_length=MAX_NAME)
    instruction: Annotated[str, Field(max_length=2000), VISIBLE] | None = Field(
        None, description="default: the task's own; the reference planner refuses any other"
    )
    seed: int = Field(0, ge=0, le=MAX_SEED, strict=True)
    planner: str | None = Field(None, json_schema_extra={"enum": list(PLANNERS)})
    segmenter: str | None = Field(None, json_schema_extra={"enum": list(SEGMENTERS)})


class BatchCreate(BaseModel):
    model_config = ConfigDict(extra="forbid")

    suite: Visible = Field("builtin", max_length=MAX_NAME, description="task suite (GET /api/catalog lists them)")
    specs: list[BatchTrial] | None = Field(
        None, max_length=2000, description="explicit trials (instead of tasks × trials from the suite)"
    )
    tasks: list[Annotated[str, Field(max_length=MAX_NAME), VISIBLE]] | None = Field(
        None, max_length=2000, description="subset of the suite's tasks (default: all)"
    )
    trials: int = Field(1, ge=1, le=100, strict=True, description="seeds per task")
    seed: int = Field(0, ge=0, le=MAX_SEED, strict=True)
    planner: str = Field("reference", json_schema_extra={"enum": list(PLANNERS)})
    model: Annotated[str, Field(max_length=200), VISIBLE] | None = Field(None, description=MODEL_NAME)
    endpoint: Annotated[str, Field(max_length=100), VISIBLE] | None = Field(
        None, description="an LLM endpoint the operator configured"
    )
    segmenter: str = Field(DEFAULT_SEGMENTER, json_schema_extra={"enum": list(SEGMENTERS)})
    protocol: str | None = Field(
        None,
        json_schema_extra={"enum": list(PROTOCOLS)},
        description="a named evaluation configuration of the paper for every trial (GET /api/catalog lists them)",
    )
    capture: bool = Field(
        False, strict=True, description="record training-data frames for every trial (for LeRobot export)"
    )


MAX_BATCH = 2000


@router.post("", status_code=202)
def create_batch(body: BatchCreate, request: Request) -> dict:
    """Every trial is checked before anything is recorded: a batch is queued whole or not at all."""
    suites = catalog_suites()
    if body.suite not in suites:
        raise HTTPException(422, f"unknown suite {body.suite!r}; available: {', '.join(suites)}")
    n = len(body.specs) if body.specs is not None else len(body.tasks or suites[body.suite]) * body.trials
    if n > MAX_BATCH:  # before expanding anything
        raise HTTPException(422, f"{n} trials is more than one batch may hold ({MAX_BATCH})")
    if body.specs is not None and not body.specs:
        raise HTTPException(422, "specs is empty: give at least one trial, or leave it out to run the suite")
    if body.specs is not None:  # each spec names its task and seed: these would be ignored, not run
        ignored = [
            f"{name} ({value!r})"
            for name, value, unset in (("tasks", body.tasks, None), ("trials", body.trials, 1), ("seed", body.seed, 0))
            if value != unset
        ]
        if ignored:
            raise HTTPException(
                422,
                f"{', '.join(ignored)}: not with specs (each spec names its own task and seed); give either specs, "
                "or tasks with trials per task from seed",
            )
    if body.tasks is not None and not body.tasks:
        raise HTTPException(422, f"tasks is empty: no tasks selected; omit `tasks` to run the whole {body.suite} suite")
    if body.tasks is not None:
        repeated = [t for t, c in Counter(body.tasks).items() if c > 1]
        if repeated:
            raise HTTPException(
                422, f"tasks: {', '.join(repeated[:10])} listed more than once (use `trials` for several seeds)"
            )
    if body.seed + body.trials - 1 > MAX_SEED:
        raise HTTPException(422, f"seed: seeds {body.seed}..{body.seed + body.trials - 1} go past {MAX_SEED}")
    if body.specs is None and body.tasks is not None:
        unknown = [t for t in dict.fromkeys(body.tasks) if t not in suites[body.suite]]
        if unknown:
            raise HTTPException(
                422, f"unknown task(s) {', '.join(unknown[:10])}; {body.suite} tasks: {', '.join(suites[body.suite])}"
            )
    if body.specs is not None:  # a batch is recorded under its suite: every spec's known task must belong to it
        known = {t for tasks in suites.values() for t in tasks}  # unknown ones: trial_config names them below
        outside = [
            f"specs[{i}]: {sp.task!r}"
            for i, sp in enumerate(body.specs)
            if sp.task in known and sp.task not in suites[body.suite]
        ]
        if outside:
            raise HTTPException(
                422, f"{'; '.join(outside[:10])} not in suite {body.suite!r} (set `suite` to the tasks' suite)"
            )
    batch_id = f"batch-{uuid.uuid4().hex[:10]}"
    if body.specs is not None:
        wanted = [
            (
                f"specs[{i}]",
                dict(
                    task=sp.task,
                    instruction=sp.instruction,
                    seed=sp.seed,
                    # unset (None) takes the batch's; an empty name is a name, refused below like any unknown one
                    planner=body.planner if sp.planner is None else sp.planner,
                    segmenter=body.segmenter if sp.segmenter is None else sp.segmenter,
                ),
            )
            for i, sp in enumerate(body.specs)
        ]
    else:
        wanted = [
            (
                f"{task} seed {body.seed + k}",
                dict(task=task, seed=body.seed + k, planner=body.planner, segmenter=body.segmenter),
            )
            for task in (body.tasks or suites[body.suite])
            for k in range(body.trials)
        ]
    configs = []
    for where, fields in wanted:
        try:
            trial = TrialCreate.model_validate(
                {
                    **fields,
                    "model": body.model,
                    "endpoint": body.endpoint,
                    "capture": body.capture,
                    "protocol": body.protocol,
                }
            )
            configs.append(trial_config(trial, batch_id))
        except ValidationError as e:  # a catalog name the batch or one of its specs got wrong
            raise HTTPException(422, f"{where}: " + "; ".join(x["msg"] for x in safe_errors(e.errors()))) from None
        except HTTPException as e:
            raise HTTPException(422, f"{where}: {e.detail}") from None
    store, runner = request.app.state.store, request.app.state.runner
    # code, packages, task files, seeds, settings, and the plan library the workers give LLM planners
    manifest = batch_manifest(body.suite, configs, batch_id, StorePlanLibrary(store))
    store.create_batch(batch_id, {**body.model_dump(), "manifest": manifest, "trial_count": len(configs)})
    for n, config in enumerate(configs):
        runner.submit(f"{batch_id}-{n:04d}-{config.task}-{config.seed}", config)
    return {"id": batch_id, "trials": len(configs), "manifest_id": manifest["id"]}


@router.get("")
def list_batches(
    request: Request, limit: int = Query(100, ge=1, le=500), offset: int = Query(0, ge=0, le=MAX_OFFSET)
) -> dict:
    """Every batch, newest first: its settings, status and progress (done / total, successes)."""
    total, items = request.app.state.store.list_batches(limit=limit, offset=offset)
    for item in items:
        manifest = item["spec"].pop("manifest", None) or {}  # large (files, packages): GET /api/batches/{id} has it
        item["spec"]["manifest_id"] = manifest.get("id")
        p = item["progress"]
        if item["status"] != "cancelled" and p["done"] >= p["total"]:
            item["status"] = "done"
    return {"total": int(total), "limit": limit, "offset": offset, "items": items}


@router.get("/{batch_id}")
def get_batch(batch_id: BatchId, request: Request) -> dict:
    """The batch: its settings (`spec`, with the run's manifest), status, progress, its trials' summaries, and
    `results`, one row per task: done / total, `judged` (trials with a verdict on the task: not aborted or
    interrupted), `not_judged`, `deleted`, `successes`, `success_rate` and `ci95` (its 95 % Wilson interval,
    [low, high]) over the judged trials. With no judged trial yet, `success_rate` and `ci95` are both null: there
    is no rate to bound."""
    return _batch_with_results(request, batch_id)


CSV_TRIAL_COLUMNS = (
    "id",
    "task",
    "seed",
    "instruction",
    "planner",
    "segmenter",
    "status",
    "verdict",
    "success",
    "failure",
    "failed_node",
    "reason",
    "wall_time_s",
    "sim_time_s",
    "cost_usd",
    "created_at",  # ISO 8601 in UTC with its offset, as the JSON has it
)


@router.get("/{batch_id}/results.csv", response_class=PlainTextResponse)
def batch_results_csv(batch_id: BatchId, request: Request) -> PlainTextResponse:
    """The per-task result table (success rate with its Wilson 95 % interval) as CSV; a task with no judged trial
    has empty success_rate, ci95_low and ci95_high cells. Text cells are spreadsheet-safe as in trials.csv."""
    b = _batch_with_results(request, batch_id)
    rows = [
        {
            "task": r["task"],
            "done": r["done"],
            "total": r["total"],
            "successes": r["successes"],
            "success_rate": r["success_rate"],
            "ci95_low": r["ci95"][0] if r["ci95"] is not None else None,  # empty cells: no judged trial
            "ci95_high": r["ci95"][1] if r["ci95"] is not None else None,
            "judged": r["judged"],
            "not_judged": r["not_judged"],
            "deleted": r["deleted"],
        }
        for r in b["results"]
    ]
    return _csv(rows, RESULT_COLUMNS, f"{batch_id}-results.csv")


# success_rate and its interval are over `judged` trials; `not_judged` (aborted, interrupted) and `deleted` beside
RESULT_COLUMNS = (
    "task",
    "done",
    "total",
    "successes",
    "success_rate",
    "ci95_low",
    "ci95_high",
    "judged",
    "not_judged",
    "deleted",
)


@router.get("/{batch_id}/trials.csv", response_class=PlainTextResponse)
def batch_trials_csv(batch_id: BatchId, request: Request) -> PlainTextResponse:
    """One row per trial of the batch (outcome, failure attribution, timings, cost, and when it was created:
    `created_at`, ISO 8601 in UTC with its offset) as CSV.

    Spreadsheet safety (OWASP, CSV injection): a text cell that starts with `=`, `+`, `-`, `@`, a tab or a carriage
    return (an instruction such as `=HYPERLINK(...)`) is written with a single quote before it (`'=HYPERLINK(...)`),
    so a spreadsheet app shows it as text instead of running it. Only this CSV does so: the JSON (GET
    /api/batches/{id}, /api/trials/{id}) and the stored record keep the text as submitted; numbers, negative ones
    too, are written as numbers."""
    b = _batch_with_results(request, batch_id)
    return _csv(b["trials"], CSV_TRIAL_COLUMNS, f"{batch_id}-trials.csv")


# A text cell starting with one of these is read as a formula by spreadsheet apps (Excel, LibreOffice, Sheets):
# `=HYPERLINK(...)` in an instruction, `-2+3` in a reason. OWASP's advice for CSV injection: prefix it with '.
FORMULA_START = ("=", "+", "-", "@", "\t", "\r")


def spreadsheet_safe(value: object) -> object:
    """A CSV cell as a spreadsheet shows it and never runs it: text that starts like a formula gets a leading
    single quote (shown as text; the quote is the only change); numbers (a negative one too), booleans and empty
    cells are written as they are."""
    if isinstance(value, str) and value.startswith(FORMULA_START):
        return "'" + value
    return value


def _csv(rows: list[dict], columns: tuple[str, ...], filename: str) -> PlainTextResponse:
    import csv
    import io

    buf = io.StringIO()
    # RFC 4180's CRLF: the writer quotes a cell holding any character of its line terminator, so a carriage return
    # inside a cell is quoted too (with "\n" alone it went out bare, and a spreadsheet began a new row at it)
    w = csv.DictWriter(buf, fieldnames=columns, extrasaction="ignore", lineterminator="\r\n")
    w.writeheader()
    w.writerows({k: spreadsheet_safe(v) for k, v in row.items()} for row in rows)
    return PlainTextResponse(
        buf.getvalue(), media_type="text/csv", headers={"content-disposition": f'attachment; filename="{filename}"'}
    )


# Trials that never got a fair attempt (cancelled, aborted by the operator, cut off by a server stop): reported
# per task as `not_judged`, never counted as failures in the success rate or its interval.
NOT_JUDGED = ("aborted", "interrupted")


def _no_batch(request: Request, batch_id: str) -> HTTPException:
    """404 naming the id; for a deleted batch, where its trials are."""
    kept = request.app.state.store.trial_ids(batch=batch_id)
    if kept:
        return HTTPException(
            404, f"no batch {batch_id!r}: it was deleted; its {len(kept)} trials are kept (GET /api/trials?batch=...)"
        )
    return HTTPException(404, f"no batch {batch_id!r}")


def _batch_with_results(request: Request, batch_id: str) -> dict:
    batch = request.app.state.store.get_batch(batch_id)
    if batch is None:
        raise _no_batch(request, batch_id)
    deleted = batch.pop("deleted_trials", [])
    # Deleted members still count: deleting a failure must not rewrite a benchmark's result.
    members = batch["trials"] + deleted
    expected = int(batch["spec"].get("trial_count") or len(members))
    finished = [t for t in members if t["status"] in ("done", "interrupted")]
    table = []
    for task in dict.fromkeys(t["task"] for t in sorted(members, key=lambda t: (t["task"], t["seed"]))):
        rs = [t for t in finished if t["task"] == task]
        judged = [t for t in rs if t.get("verdict") not in NOT_JUDGED]
        k = sum(bool(t["success"]) for t in judged)
        table.append(
            {
                "task": task,
                "done": len(rs),
                "total": sum(t["task"] == task for t in members),
                "judged": len(judged),
                "not_judged": len(rs) - len(judged),
                "deleted": sum(t["task"] == task for t in deleted),
                "successes": k,
                "success_rate": k / len(judged) if judged else None,
                # no judged trial, no rate: no interval either (wilson's [0, 0] read as "certainly never succeeds")
                "ci95": list(wilson(k, len(judged))) if judged else None,
            }
        )
    status = batch["status"] if batch["status"] == "cancelled" or len(finished) < len(members) else "done"
    progress = {
        "done": len(finished),
        "total": len(members),
        "deleted": len(deleted),
        "purged": max(0, expected - len(members)),  # gone for good: the results no longer hold them
    }
    return {**batch, "status": status, "progress": progress, "results": table}


@router.post("/{batch_id}/cancel")
def cancel_batch(batch_id: BatchId, request: Request) -> dict:
    store, runner = request.app.state.store, request.app.state.runner
    batch = store.get_batch(batch_id)
    if batch is None:
        raise HTTPException(404, f"no batch {batch_id!r}")
    if batch["status"] == "cancelled":
        raise HTTPException(409, f"batch {batch_id!r} is already cancelled")
    pending = [t for t in batch["trials"] if t["status"] in ("queued", "running")]
    if not pending:
        raise HTTPException(409, f"batch {batch_id!r} has already finished: nothing to cancel")
    live = runner.live
    # count only trials this call stops: one whose control was already aborted (cancelled before) is not new
    cancelled = sum(runner.cancel(t["id"]) for t in pending if not (t["id"] in live and live[t["id"]].control.aborted))
    store.set_batch_status(batch_id, "cancelled")
    return {"id": batch_id, "cancelled": cancelled}


class BatchDeleted(BaseModel):
    id: str
    trials_kept: int = Field(description="its trials, still in the history and still naming the batch")


@router.delete("/{batch_id}", response_model=BatchDeleted)
def delete_batch(batch_id: BatchId, request: Request) -> BatchDeleted:
    """Remove a finished or cancelled batch's record (its settings, manifest and result table). Nothing recorded
    is lost: its trials stay in the history, each still naming the batch (`batch_id`; GET /api/trials/{id} says
    `batch_deleted: true`, and GET /api/trials?batch=... lists them). 409 while any of its trials is queued or
    running."""
    store, runner = request.app.state.store, request.app.state.runner
    batch = store.get_batch(batch_id)
    if batch is None:
        raise _no_batch(request, batch_id)
    members = batch["trials"] + batch["deleted_trials"]
    live = runner.live
    pending = [t for t in members if t["status"] in ("queued", "running") or t["id"] in live]
    if pending:
        if batch["status"] == "cancelled":
            raise HTTPException(
                409,
                f"batch {batch_id!r} is cancelled but {len(pending)} of its trials are still stopping: "
                "delete it once they have",
            )
        raise HTTPException(
            409,
            f"batch {batch_id!r} is still running ({len(pending)} of its {len(members)} trials queued or running): "
            f"cancel it first (POST /api/batches/{batch_id}/cancel), then delete it",
        )
    if not store.delete_batch(batch_id):  # deleted meanwhile by another request
        raise _no_batch(request, batch_id)
    return BatchDeleted(id=batch_id, trials_kept=len(members))


@router.get("/{batch_id}/timing")
def batch_timing(batch_id: BatchId, request: Request) -> dict:
    """Where each task's time went. `rows`: per primitive of its plans, mean simulated and wall seconds per run of
    each primitive kind over the batch's finished trials. `phases`: per phase of the trial pipeline (setup,
    perception, planning, execution, ...), mean wall seconds per finished trial that recorded its phases."""
    from spark_core import REGISTRY

    primitives = {spec.name for spec in REGISTRY}  # the tree's leaves; composites only hold them
    store = request.app.state.store
    batch = store.get_batch(batch_id)
    if batch is None:
        raise _no_batch(request, batch_id)
    sums: dict[tuple[str, str], list[float]] = {}  # (task, primitive) -> [runs, sim s, wall s]
    for t in batch["trials"]:
        if t["status"] != "done":
            continue
        trial = store.get_trial(t["id"]) or {}
        for node in (trial.get("nodes") or {}).values():
            if node.get("kind") not in primitives or node.get("started_t") is None:
                continue
            acc = sums.setdefault((t["task"], node["kind"]), [0, 0.0, 0.0])
            acc[0] += 1
            acc[1] += node.get("sim_time_s") or 0.0
            acc[2] += node.get("duration_s") or 0.0
    rows = [
        {"task": task, "primitive": kind, "runs": n, "mean_sim_s": round(sim / n, 4), "mean_wall_s": round(wall / n, 4)}
        for (task, kind), (n, sim, wall) in sums.items()
    ]
    # phases_s is in the trials' summaries (stored since revision 0009; older trials have none and are not counted)
    timed = [t for t in batch["trials"] if t["status"] == "done" and t.get("phases_s")]
    phase_sums: dict[tuple[str, str], float] = {}
    for t in timed:
        for phase, wall_s in t["phases_s"].items():
            phase_sums[(t["task"], phase)] = phase_sums.get((t["task"], phase), 0.0) + float(wall_s)
    per_task = {task: sum(t["task"] == task for t in timed) for task in {t["task"] for t in timed}}
    phases = [
        {"task": task, "phase": phase, "trials": per_task[task], "mean_wall_s": round(total / per_task[task], 4)}
        for (task, phase), total in phase_sums.items()
    ]
    return {"id": batch_id, "rows": rows, "phases": phases}
