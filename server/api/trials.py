"""Trials: create (queued for a worker), list, get, delete (undoable for a grace period) and restore,
step-through control, live events."""

from __future__ import annotations

import asyncio
import os
import re
import time
import uuid
from datetime import timedelta
from typing import Annotated

from fastapi import APIRouter, HTTPException, Path, Query, Request, Response, WebSocket, WebSocketDisconnect

from spark_core import CatalogError, ProtocolError, TrialConfig, TrialConfigError

from .auth import websocket_allowed
from .models import MAX_ID, MAX_OFFSET, Control, TrialCreate, TrialCreated, TrialDeleted, TrialPage, TrialRestored
from .streams import GONE, finish, watch_disconnect

router = APIRouter(prefix="/api/trials", tags=["trials"])
TrialId = Annotated[str, Path(max_length=MAX_ID)]


@router.post("", status_code=202, response_model=TrialCreated)
def create_trial(body: TrialCreate, request: Request) -> TrialCreated:
    config = trial_config(body)
    check_breakpoints(list(body.breakpoints), config)
    trial_id = f"{body.task}-{uuid.uuid4().hex[:10]}"
    request.app.state.runner.submit(trial_id, config)
    return TrialCreated(id=trial_id, status="queued")


def trial_config(body: TrialCreate, batch_id: str | None = None) -> TrialConfig:
    """The request as a checked TrialConfig; 422 naming the field and what was expected."""
    from spark_core import PLANNERS

    entry = PLANNERS[body.planner]
    if body.model is not None and entry.offline and not entry.needs_model and entry.default_model is None:
        raise HTTPException(422, f"model: the {body.planner} planner takes no model (only the LLM planners do)")
    # a model name is an identifier: "   " is none (it passed "needs a model name" and went to the LLM server as is)
    model = None if body.model is None else body.model.strip()
    if model == "":
        default = entry.default_model
        raise HTTPException(
            422,
            "model: the model name is blank: name a model"
            + (f", or leave it out for the {body.planner} planner's default ({default})" if default else ""),
        )
    if model is not None:  # Gemini puts it into its URL's path: only the characters model names are made of
        from .model_names import model_name_problem

        problem = model_name_problem(body.planner, model)
        if problem is not None:
            raise HTTPException(422, problem)
    # a blank instruction is no instruction: the task's own, as the field's description says (not a planner's
    # refusal of "   ")
    instruction = body.instruction.strip() or None if body.instruction is not None else None
    if instruction is not None and body.plan is None and not entry.reads_instruction:
        from spark_core import check_task

        try:
            own = check_task(body.task).instruction
        except CatalogError:
            own = None  # an unknown task: config.check() below names it
        if own is not None and instruction != own.strip():
            # a planner that reads no instruction runs the task's hand-written plan: an instruction would be
            # recorded (and shown) as what ran while the robot did something else
            readers = [p for p in PLANNERS.values() if p.reads_instruction]
            choices = [f"the {p.name} planner (offline)" for p in readers if p.offline]
            choices += ["an LLM planner"] if any(not p.offline for p in readers) else []
            raise HTTPException(
                422,
                f"instruction: the {body.planner} planner runs {body.task!r}'s own hand-written plan ({own!r}) and "
                f"does not read an instruction; choose {' or '.join(choices)} to run this instruction, or leave "
                "the instruction out",
            )
    capture = None
    if body.capture:
        from spark_core import CaptureConfig

        capture = CaptureConfig()
    config = TrialConfig(
        body.task,
        instruction=instruction,
        planner=body.planner,
        model=model,
        base_url=None,  # never a caller's URL: endpoints are the operator's (named in spark.yaml)
        plan_text=body.plan,
        segmenter=body.segmenter,
        endpoint=body.endpoint,
        embodiment=body.embodiment,
        seed=body.seed,
        recovery=body.recovery,
        adaptive=body.adaptive,
        capture=capture,
        time_limit_s=body.time_limit_s,
        pacing=body.pacing,
        breakpoints=tuple(body.breakpoints),
        start_paused=body.start_paused,
        batch_id=batch_id,
    )
    try:
        if body.protocol is not None:
            from spark_core import apply_protocol

            config = apply_protocol(body.protocol, config)  # its settings, then may it be reported under it
        config = config.check()
    except (TrialConfigError, ProtocolError) as e:
        message = str(e)  # named as the request names it: the body's field is `plan`
        raise HTTPException(
            422, "plan:" + message[len("plan_text:") :] if message.startswith("plan_text:") else message
        ) from None
    if config.plan_text is not None:  # a given plan's arm tags: refused now, not when the node runs
        from spark_core import check_task, validate

        from .arms import arm_problem

        plan = validate(config.plan_text)[0]
        default = check_task(config.task).embodiments[0]
        problem = arm_problem(plan, config.embodiment or default, config.task, config.embodiment is None)
        if problem:
            raise HTTPException(422, problem)
    return config


@router.get("", response_model=TrialPage)
def list_trials(
    request: Request,
    status: str | None = Query(None, max_length=16),
    task: str | None = Query(None, max_length=128),
    success: bool | None = None,
    verdict: str | None = Query(None, max_length=32),
    batch: str | None = Query(None, max_length=64),
    q: str | None = Query(None, max_length=200),
    training: bool | None = Query(
        None, description="only trials with (true) or without (false) training data (a capture, for LeRobot export)"
    ),
    sort: str = Query("-created_at", max_length=32),
    limit: int = Query(50, ge=1, le=500),
    offset: int = Query(0, ge=0, le=MAX_OFFSET),
) -> TrialPage:
    from spark_core import enums

    verdicts = enums()["verdict"]
    if sort.startswith("--"):  # the store drops every leading '-': "--created_at" sorted as "-created_at"
        raise HTTPException(422, f"sort: {sort!r}: a column name, with one '-' before it for descending")
    if verdict and verdict not in verdicts:
        raise HTTPException(422, f"verdict: unknown verdict {verdict!r}; verdicts: {', '.join(verdicts)}")
    try:
        total, items = request.app.state.store.list_trials(
            status=status,
            task=task,
            success=success,
            search=q,
            sort=sort,
            limit=limit,
            offset=offset,
            verdict=verdict,
            batch=batch,
            training=training,
        )
    except ValueError as e:
        raise HTTPException(422, str(e)) from None
    return TrialPage(total=total, limit=limit, offset=offset, items=items)


@router.get("/{trial_id}")
def get_trial(trial_id: TrialId, request: Request) -> dict:
    trial = request.app.state.store.get_trial(trial_id)
    if trial is None:
        raise HTTPException(404, f"no trial {trial_id!r}")
    # files are served by name (GET .../artifacts/{name}); where they lie on the server is nobody's business
    trial["artifacts"] = [{k: v for k, v in a.items() if k != "path"} for a in trial.get("artifacts") or []]
    if trial.get("batch_id"):  # a deleted batch's trials are kept, naming it: say it is gone (no link to follow)
        trial["batch_deleted"] = not request.app.state.store.has_batch(trial["batch_id"])
    live = request.app.state.runner.live.get(trial_id)
    if live is not None:  # still running: the stored events lag, serve the live ones
        trial["events"] = list(live.history)
        trial["control_state"] = live.control.state
        trial["breakpoints"] = sorted(live.control.breakpoints)  # a reopened page shows the ones already set
        trial["worker_pid"] = live.worker_pid
    return trial


@router.get("/{trial_id}/artifacts/{name}")
def artifact(trial_id: TrialId, name: Annotated[str, Path(max_length=256)], request: Request):
    """A file the trial record references (served only if the record names it; its hash is in the record)."""
    from fastapi.responses import FileResponse

    trial = request.app.state.store.get_trial(trial_id)
    entry = next((a for a in (trial or {}).get("artifacts", []) if a["name"] == name), None)
    if entry is None:
        raise HTTPException(404, f"trial {trial_id!r} has no artifact {name!r}")
    if not os.path.isfile(entry["path"]):  # removed from disk since (or another artifacts directory): no 500
        raise HTTPException(404, f"trial {trial_id!r}: artifact {name!r} is no longer on this server's disk")
    media = "image/jpeg" if str(entry["path"]).endswith((".jpg", ".jpeg")) else "image/png"
    return FileResponse(entry["path"], media_type=media)


@router.get("/{trial_id}/camera.png", response_class=Response, responses={200: {"content": {"image/png": {}}}})
def camera_at(
    trial_id: TrialId,
    request: Request,
    t_sim_s: float = Query(ge=0, le=1e6, description="simulated seconds since the trial started"),
    camera: str | None = Query(None, max_length=128, description="default: the scene's first camera"),
) -> Response:
    """A finished trial's camera at a time: the recorded scene state at or before `t_sim_s`, rendered, with the
    keypoints grounded by then drawn (the page's camera panel at its time cursor)."""
    from ..view3d.replay import ReplayUnavailable

    try:
        png = request.app.state.replays.camera_png(trial_id, camera, t_sim_s)
    except KeyError:
        raise HTTPException(404, f"no trial {trial_id!r}") from None
    except ReplayUnavailable as e:
        raise HTTPException(409, str(e)) from None
    return Response(png, media_type="image/png", headers={"cache-control": "max-age=3600"})


@router.delete("/{trial_id}", response_model=TrialDeleted)
def delete_trial(
    trial_id: TrialId,
    request: Request,
    purge: bool = Query(False, description="remove the record and its files now (cannot be undone)"),
) -> TrialDeleted:
    """Hide the trial from every list, page and export; `POST .../restore` brings it back within the grace
    period (SPARK_DELETE_GRACE_S, 24 h by default), after which it is purged with its artifact files."""
    live = request.app.state.runner.live.get(trial_id)
    if live is not None:
        state = "running" if live.sent else "queued"
        raise HTTPException(409, f"trial {trial_id!r} is still {state}: abort it first")
    store, settings = request.app.state.store, request.app.state.settings
    if purge:
        if not store.purge_trial(trial_id, settings.artifacts_dir):
            raise HTTPException(404, f"no trial {trial_id!r}")
        request.app.state.replays.forget(trial_id)  # its camera images and 3D replay go with it
        return TrialDeleted(id=trial_id, purged=True, restore_until=None)
    deleted_at = store.delete_trial(trial_id)
    if deleted_at is None:
        raise HTTPException(404, f"no trial {trial_id!r}")
    request.app.state.replays.forget(trial_id)
    until = deleted_at + timedelta(seconds=settings.delete_grace_s)
    return TrialDeleted(id=trial_id, purged=False, restore_until=until.isoformat())


@router.post("/{trial_id}/restore", response_model=TrialRestored)
def restore_trial(trial_id: TrialId, request: Request) -> TrialRestored:
    """Undo a delete made within the grace period."""
    grace_s = request.app.state.settings.delete_grace_s
    if not request.app.state.store.restore_trial(trial_id, grace_s):
        raise HTTPException(
            404, f"no deleted trial {trial_id!r} to restore (a deletion can be undone for {grace_s / 3600:g} h)"
        )
    return TrialRestored(id=trial_id, restored=True)


@router.post("/{trial_id}/replay", status_code=202)
def replay(trial_id: TrialId, request: Request, speed: float = Query(1.0, gt=0.0, le=20.0)) -> dict:
    """Replay a finished trial in the 3D view from its recorded scene states (`speed`x real time)."""
    from ..view3d.replay import ReplayUnavailable, start_replay

    scene = request.app.state.scene
    if scene is None:
        raise HTTPException(409, "the 3D view is off (SPARK_VISER=0)")
    try:
        return start_replay(request.app.state.store, scene, trial_id, speed)
    except KeyError:
        raise HTTPException(404, f"no trial {trial_id!r}") from None
    except ReplayUnavailable as e:
        raise HTTPException(409, str(e)) from None


@router.post("/{trial_id}/control")
def control(trial_id: TrialId, body: Control, request: Request) -> dict:
    live = request.app.state.runner.live.get(trial_id)
    if live is None:
        if not request.app.state.store.trial_ids(ids=(trial_id,)):
            raise HTTPException(404, f"no trial {trial_id!r}")
        raise HTTPException(409, f"trial {trial_id!r} is not queued or running")
    c = live.control
    if body.breakpoints is not None and body.action != "breakpoints":
        raise HTTPException(422, f"breakpoints: only with action 'breakpoints', not {body.action!r}")
    if body.action == "breakpoints" and body.breakpoints is None:  # left out is not "clear them all"
        raise HTTPException(
            422,
            "breakpoints: action 'breakpoints' sets the list given in `breakpoints` (the node paths to pause "
            "before; [] clears them): give it",
        )
    if c.aborted and body.action != "abort":
        raise HTTPException(409, f"trial {trial_id!r} was aborted: it cannot {body.action} any more")
    if body.action == "breakpoints":
        c.set_breakpoints(check_breakpoints(body.breakpoints or [], live.config))
    else:
        getattr(c, body.action)()
    return {"id": trial_id, "state": c.state, "breakpoints": sorted(c.breakpoints)}


_NODE_PATH = re.compile(r"tree(\.children\[(0|[1-9][0-9]*)\])*")  # spark_core.grammar's walk(): the root, children


def check_breakpoints(paths: list[str], config: TrialConfig) -> list[str]:
    """The paths, if each names a node of the trial's plan (when the plan is known before it runs: a given plan
    or the task's reference plan); 422 naming the unknown ones and a few that exist."""
    from spark_core import TASKS, validate

    text = config.plan_text
    if text is None and config.planner == "reference":
        text = TASKS[config.task].reference_plan_text()
    plan = validate(text)[0] if text is not None else None
    if plan is None:  # an LLM's plan: its node paths are known only once it is written, but a path is a path
        malformed = [p for p in paths if not _NODE_PATH.fullmatch(p)]
        if malformed:
            raise HTTPException(
                422,
                f"breakpoints: {', '.join(repr(p) for p in malformed[:5])} is not a node path (the plan is written "
                "when the trial runs; node paths look like tree, tree.children[0], tree.children[2].children[1])",
            )
        return paths
    nodes = [path for path, _node, _arm in plan.nodes()]
    unknown = [p for p in paths if p not in nodes]
    if unknown:
        raise HTTPException(
            422,
            f"breakpoints: no node {', '.join(repr(p) for p in unknown[:5])} in the trial's plan; "
            f"its nodes: {', '.join(nodes[:8])}{' ...' if len(nodes) > 8 else ''}",
        )
    return paths


def _stamped(ev: dict) -> dict:
    """The event as sent over the live stream: with `sent_s`, the server's Unix time of sending."""
    return {**ev, "sent_s": time.time()}


@router.websocket("/{trial_id}/events")
async def events(websocket: WebSocket, trial_id: str) -> None:
    """Every event of the trial (history first), then live ones; closes when the trial ends. Each message carries
    `sent_s`, the server's Unix time when it was sent: a page opened mid-trial reads the server's clock from it (a
    replayed event's own `wall_s` is as old as the event)."""
    if not await websocket_allowed(websocket, trial_id=trial_id):
        return
    await websocket.accept()
    runner = websocket.app.state.runner
    loop = asyncio.get_running_loop()
    q: asyncio.Queue = asyncio.Queue()
    unsubscribe = runner.subscribe(trial_id, lambda ev: loop.call_soon_threadsafe(q.put_nowait, ev))
    watcher = watch_disconnect(websocket, q)
    try:
        if trial_id not in runner.live:  # finished (or unknown): replay what the store has
            trial = websocket.app.state.store.get_trial(trial_id)
            for ev in (trial or {}).get("events", []):
                await websocket.send_json(_stamped(ev))
            await websocket.send_json(_stamped({"kind": "closed"}))
            return
        while (ev := await q.get()) is not GONE:
            await websocket.send_json(_stamped(ev))
            if ev.get("kind") == "closed":
                return
    except WebSocketDisconnect:
        pass
    finally:
        unsubscribe()
        await finish(websocket, watcher)


dashboard = APIRouter(tags=["trials"])


@dashboard.websocket("/api/events")
async def all_events(websocket: WebSocket) -> None:
    """Dashboard stream: {kind: trial, id, status, ...} whenever any trial is queued, starts or ends."""
    if not await websocket_allowed(websocket):
        return
    await websocket.accept()
    loop = asyncio.get_running_loop()
    q: asyncio.Queue = asyncio.Queue()
    unwatch = websocket.app.state.runner.watch(lambda ev: loop.call_soon_threadsafe(q.put_nowait, ev))
    watcher = watch_disconnect(websocket, q)
    try:
        while (ev := await q.get()) is not GONE:
            await websocket.send_json(ev)
    except WebSocketDisconnect:
        pass
    finally:
        unwatch()
        await finish(websocket, watcher)
