"""Trial runner: queued trials go to a pool of worker processes (one slot thread per process). Each live trial
keeps its event history and a step-through control that forwards to its worker; every event is fanned out to
live subscribers, and the 3D view follows the most recently started trial.

A worker that dies (crash, kill, out of memory) or stops responding (no message for `hang_timeout_s`; a running
trial streams 3D poses at ~30 Hz, so silence means it is stuck) fails its trial with the reason; the slot
starts a fresh process for the next trial and the console carries on.

On shutdown, running trials are stopped and recorded as interrupted (within a deadline: a server must stop in
seconds); queued ones stay queued in the store, and the next start queues them again from their recorded
config."""

from __future__ import annotations

import contextlib
import functools
import queue
import threading
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

from spark_core import (
    StepControl,
    TraceStore,
    TrialConfig,
    TrialConfigError,
    Verdict,
    check_task,
    config_from_record,
    config_record,
)

from .worker import WorkerProcess

__all__ = ["TrialRunner", "RemoteControl", "Live"]


class RemoteControl(StepControl):
    """The console's side of a trial's step-through control: remembers the operator's choices (so a queued
    trial starts with them) and forwards each one to the worker running the trial. `paused_at` follows the
    trial's own paused/started events."""

    def __init__(self, breakpoints=()):
        super().__init__(breakpoints)
        self._forward: Callable[[str, object], None] | None = None

    def attach(self, forward: Callable[[str, object], None]) -> dict:
        """Start forwarding; returns the state the worker starts from."""
        with self._cond:
            self._forward = forward
            return {
                "paused": self._paused,
                "aborted": self._aborted,
                "breakpoints": sorted(self._breakpoints),
                "steps": self._step_budget,  # steps asked for while queued: each lets one more node run
            }

    def _send(self, action: str, arg=None) -> None:
        if self._forward is not None:
            self._forward(action, arg)

    def pause(self) -> None:
        super().pause()
        self._send("pause")

    def resume(self) -> None:
        super().resume()
        self.paused_at = None  # released now: the answer says running, not the pause the worker is leaving
        self._send("resume")

    def step(self) -> None:
        super().step()
        self.paused_at = None  # one node runs, then it pauses again ("pausing" until the worker says so)
        self._send("step")

    def abort(self) -> None:
        super().abort()
        self._send("abort")

    def set_breakpoints(self, paths) -> None:
        super().set_breakpoints(paths)
        self._send("breakpoints", sorted(self.breakpoints))

    def observe(self, ev: dict) -> None:
        self.paused_at = ev["node_path"] if ev.get("kind") == "paused" else None


@dataclass
class Live:
    """A queued or running trial's handles."""

    config: TrialConfig
    control: RemoteControl
    history: list[dict] = field(default_factory=list)  # every event so far
    subscribers: list[Callable[[dict], None]] = field(default_factory=list)
    worker_pid: int | None = None
    sent: bool = False  # handed to a worker process: it is running
    stopped_by_shutdown: bool = False  # the server (not the operator) stopped it


class TrialRunner:
    def __init__(
        self,
        store: TraceStore,
        workers: int = 2,
        scene=None,
        artifacts_dir: str = "var/artifacts",
        hang_timeout_s: float = 120.0,
        spawn_at_start: bool = False,
    ):
        self.store = store
        self.artifacts_dir = artifacts_dir
        self.scene = scene  # ViserScene showing the most recently started trial, or None
        self.hang_timeout_s = hang_timeout_s
        self.queue: queue.Queue[str | None] = queue.Queue()
        self.live: dict[str, Live] = {}
        self.watchers: list[Callable[[dict], None]] = []  # dashboard: every trial's status changes
        self.processes: list[WorkerProcess | None] = [None] * workers
        self._lock = threading.Lock()
        self._closing = False
        self.threads = [
            threading.Thread(target=self._slot, args=(i, spawn_at_start), name=f"trial-slot-{i}", daemon=True)
            for i in range(workers)
        ]
        for t in self.threads:
            t.start()

    # -- dashboard ----------------------------------------------------------------------------------------------
    def watch(self, callback: Callable[[dict], None]) -> Callable[[], None]:
        with self._lock:
            self.watchers.append(callback)

        def unwatch() -> None:
            with self._lock:
                if callback in self.watchers:
                    self.watchers.remove(callback)

        return unwatch

    def _announce(self, trial_id: str, status: str, **extra) -> None:
        with self._lock:
            watchers = list(self.watchers)
        for cb in watchers:
            cb({"kind": "trial", "id": trial_id, "status": status, **extra})

    # -- operator -----------------------------------------------------------------------------------------------
    def submit(self, trial_id: str, config: TrialConfig) -> None:
        """Queue a checked config; its row is recorded at once (status queued)."""
        self._track(trial_id, config)
        self.store.create_trial(
            trial_id,
            status="queued",
            task=config.task,
            instruction=config.instruction or check_task(config.task).instruction,
            seed=config.seed,
            planner=config.planner,
            segmenter=config.segmenter,
            protocol={"config": _config_record(config)},
            batch_id=config.batch_id,
        )
        self._announce(trial_id, "queued", task=config.task)
        self.queue.put(trial_id)

    def requeue_recorded(self) -> tuple[int, int]:
        """At start-up: trials a previous server queued but never started run now, as they were asked for (from
        the config recorded at queue time). One that cannot be rebuilt is marked interrupted with why.
        Returns (queued again, interrupted)."""
        again = lost = 0
        batch_cancelled: dict[str, bool] = {}
        for rec in self.store.queued_trials():
            try:
                config = config_from_record(rec["protocol"].get("config") or {})
                if config.batch_id is not None and config.batch_id not in batch_cancelled:
                    batch = self.store.get_batch(config.batch_id)
                    batch_cancelled[config.batch_id] = batch is not None and batch["status"] == "cancelled"
            except TrialConfigError as e:
                self.store.update_trial(
                    rec["id"],
                    status="interrupted",
                    outcome="aborted",
                    verdict=Verdict.INTERRUPTED.value,
                    success=False,
                    reason=f"the server stopped before the trial started, and it cannot be queued again: {e}",
                )
                lost += 1
                continue
            if config.batch_id is not None and batch_cancelled[config.batch_id]:
                # its batch was cancelled by a server that stopped (or died) before recording this trial so
                self._record_cancelled(rec["id"])
                continue
            self._track(rec["id"], config)
            self.queue.put(rec["id"])
            again += 1
        return again, lost

    def _track(self, trial_id: str, config: TrialConfig) -> Live:
        live = Live(config, RemoteControl(config.breakpoints))
        if config.start_paused:
            live.control.pause()  # stops before the first primitive: set breakpoints on the tree, then resume
        with self._lock:
            self.live[trial_id] = live
        return live

    def cancel(self, trial_id: str) -> bool:
        """A queued trial is dropped before it runs (recorded as cancelled); a running one is aborted."""
        with self._lock:
            live = self.live.get(trial_id)
        if live is None:
            return False
        live.control.abort()
        return True

    def subscribe(self, trial_id: str, callback: Callable[[dict], None]) -> Callable[[], None]:
        with self._lock:
            live = self.live.get(trial_id)
            if live is None:
                return lambda: None
            live.subscribers.append(callback)
            history = list(live.history)
        for ev in history:
            callback(ev)

        def unsubscribe() -> None:
            with self._lock:
                if callback in live.subscribers:
                    live.subscribers.remove(callback)

        return unsubscribe

    def _fan_out(self, live: Live, ev: dict) -> None:
        with self._lock:
            if ev.get("kind") != "closed":
                live.history.append(ev)
            subs = list(live.subscribers)
        for cb in subs:
            cb(ev)

    def shutdown(self, timeout_s: float = 3.0) -> None:
        """Stop within `timeout_s`: running trials are aborted and recorded as interrupted; queued ones stay
        queued in the store (the next start runs them); worker processes exit, or are killed."""
        deadline = time.monotonic() + timeout_s
        self._closing = True
        with self._lock:
            running = [(tid, live) for tid, live in self.live.items() if live.sent]
            cancelled = [tid for tid, live in self.live.items() if not live.sent and live.control.aborted]
        for trial_id in cancelled:  # still queued in the store: the next start would run what was cancelled
            with contextlib.suppress(Exception):  # the store may be going away with the process
                self._record_cancelled(trial_id)
        for _, live in running:
            if not live.control.aborted:  # an operator's abort stays the operator's
                live.stopped_by_shutdown = True
                live.control.abort()
        for _ in self.threads:
            self.queue.put(None)
        for t in self.threads:
            t.join(max(0.0, deadline - time.monotonic() - 0.5))
        workers = [p for p in self.processes if p is not None]
        for p in workers:  # all at once: each exits in parallel
            p.send("stop")
        for p in workers:
            p.process.join(max(0.1, deadline - time.monotonic()))
            p.kill()
        for trial_id, live in running:  # still not recorded (its slot did not finish in time): say so now
            if live.stopped_by_shutdown:
                self._mark_interrupted(trial_id)

    def _record_cancelled(self, trial_id: str) -> None:
        """A trial cancelled (aborted) while it was queued: done, never started."""
        self.store.update_trial(
            trial_id,
            status="done",
            outcome="aborted",
            verdict=Verdict.ABORTED.value,
            success=False,
            reason="cancelled before it started",
        )

    def _mark_interrupted(self, trial_id: str) -> None:
        """A trial the server stopped at shutdown: interrupted, unless it had already ended on its own."""
        with contextlib.suppress(Exception):  # the store may be going away with the process
            trial = self.store.get_trial(trial_id) or {}
            if trial and trial.get("verdict") in (None, Verdict.ABORTED.value, Verdict.CRASHED.value):
                self.store.update_trial(
                    trial_id,
                    status="interrupted",
                    outcome="aborted",
                    verdict=Verdict.INTERRUPTED.value,
                    success=False,
                    reason="the server shut down while the trial was running",
                )

    # -- slots --------------------------------------------------------------------------------------------------
    def _slot(self, i: int, spawn_at_start: bool) -> None:
        if spawn_at_start:
            # On failure: retried when the first trial arrives, which then fails with the reason if it still
            # cannot start.
            with contextlib.suppress(RuntimeError):
                self._worker(i)
        while (trial_id := self.queue.get()) is not None:
            live = self.live[trial_id]
            if self._closing:  # not started: it stays queued in the store, and the next start runs it
                with self._lock:
                    self.live.pop(trial_id, None)
                self._fan_out(live, {"kind": "closed"})
                continue
            t0 = time.perf_counter()
            try:
                if live.control.aborted:  # cancelled while queued: never starts
                    self._record_cancelled(trial_id)
                    continue
                try:
                    worker = self._worker(i)
                except RuntimeError:
                    if self._closing:
                        continue  # stopped while its worker warmed up: still queued, as above
                    raise
                live.worker_pid = worker.pid
                state = live.control.attach(functools.partial(_forward, worker, trial_id))
                live.sent = True
                worker.send("run", trial_id, live.config, state)
                failure = self._pump(trial_id, live, worker)
                if failure:
                    worker.kill()
                    self.processes[i] = None
                    self._record_failure(trial_id, live, failure, time.perf_counter() - t0)
            except Exception as e:
                self._record_failure(
                    trial_id, live, f"internal error: {type(e).__name__}: {e}", time.perf_counter() - t0
                )
            finally:
                if live.stopped_by_shutdown:
                    self._mark_interrupted(trial_id)
                with self._lock:
                    self.live.pop(trial_id, None)
                self._fan_out(live, {"kind": "closed"})
                final = self.store.get_trial(trial_id) or {}
                self._announce(
                    trial_id, final.get("status", "done"), success=final.get("success"), verdict=final.get("verdict")
                )

    def _worker(self, i: int) -> WorkerProcess:
        p = self.processes[i]
        if p is None or not p.alive:
            p = self.processes[i] = WorkerProcess(
                self.store.url,
                self.artifacts_dir,
                self.scene.rate_hz if self.scene else 30.0,
                cancelled=lambda: self._closing,
            )
        return p

    def _pump(self, trial_id: str, live: Live, worker: WorkerProcess) -> str | None:
        """Relay the worker's messages until the trial is done. Returns why the worker failed, or None."""
        last = time.monotonic()
        key, scene = trial_id, self.scene
        draw = scene.sink(key, f"{trial_id} ({live.config.task})") if scene is not None else None
        while True:
            msg = worker.recv(0.5)
            if msg is None:
                if not worker.alive:
                    return f"worker process {worker.pid} died ({worker.death()}) while running the trial"
                if time.monotonic() - last > self.hang_timeout_s:
                    return (
                        f"worker process {worker.pid} stopped responding for {self.hang_timeout_s:.0f} s and was killed"
                    )
                continue
            last = time.monotonic()
            kind = msg[0]
            if kind == "eof":
                return f"worker process {worker.pid} died ({worker.death()}) while running the trial"
            if msg[1] != trial_id:
                continue  # a late message of an earlier trial
            payload: Any = msg[2] if len(msg) > 2 else None
            if kind == "done":
                return None
            if kind == "event":
                live.control.observe(payload)
                self._fan_out(live, payload)
                if scene is not None and payload.get("kind") in ("started", "paused"):
                    d = payload.get("detail", {})
                    what = d.get("primitive") or d.get("kind") or ""
                    scene.active(
                        key,
                        f"**Trial:** {trial_id}  \n**{payload['kind'].capitalize()}:** `{payload['node_path']}` {what}",
                    )
            elif kind == "status":
                self._announce(trial_id, payload, task=live.config.task)
            elif draw is not None:
                draw(kind, payload)

    def _record_failure(self, trial_id: str, live: Live, reason: str, wall_s: float) -> None:
        """The worker could not finish the trial: keep every event it streamed, and say why it failed."""
        trial = self.store.get_trial(trial_id) or {}
        if trial.get("status") == "done":
            return  # the worker recorded its outcome before it went away
        if not trial.get("events") and live.history:
            self.store.add_events(trial_id, live.history)
        self.store.update_trial(
            trial_id,
            status="done",
            outcome="failure",
            success=False,
            failure="worker",
            verdict=Verdict.CRASHED.value,
            reason=reason,
            wall_time_s=round(wall_s, 3),
        )


def _forward(worker: WorkerProcess, trial_id: str, action: str, arg: object) -> None:
    """An operator's step-through command, sent to the worker running the trial."""
    worker.send("control", trial_id, action, arg)


def _config_record(config: TrialConfig) -> dict:
    """The submitted config as JSON (what the operator asked for, kept even if the worker never starts), in full:
    a restart queues the trial again from it."""
    return config_record(config)
