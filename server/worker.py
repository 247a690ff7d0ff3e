"""Trial worker processes. Each trial runs in a separate process (spawned, one trial at a time), so a crash, a
hang or a leak in one trial never takes the console down.

Wire protocol (tuples over two one-way pipes):
  console -> worker: ("run", trial_id, TrialSpec, control_state) | ("control", trial_id, action, arg) | ("stop",)
  worker -> console: ("ready", pid) | ("status", trial_id, status) | ("event", trial_id, event_dict)
                     | ("scene" | "poses" | "markers" | "image", trial_id, payload) | ("done", trial_id)
The worker writes the trial record itself (same store URL); the console only records what a dead worker could not.
"""

from __future__ import annotations

import multiprocessing as mp
import os
import signal
import threading
import time
import traceback
from dataclasses import asdict, dataclass
from pathlib import Path
from typing import Any, Callable

EOF_MSG = ("eof",)  # the worker's end of the pipe closed: it exited or was killed


@dataclass(frozen=True)
class TrialSpec:
    task: str
    instruction: str
    planner: str = "reference"  # reference | rules | gemini | openai
    resolver: str = "sim"
    seed: int = 0
    breakpoints: tuple[str, ...] = ()
    model: str | None = None
    base_url: str | None = None
    start_paused: bool = False
    capture: bool = False  # training-data frames (spark_core.sim.capture) for `spark export`
    embodiment: str | None = None  # panda | ur10 | bimanual (default: the task's own)


class WorkerProcess:
    """The console's handle on one worker process."""

    def __init__(self, store_url: str, artifacts_dir: str, feed_hz: float = 30.0, ready_timeout_s: float = 300.0,
                 cancelled: Callable[[], bool] = lambda: False):
        ctx = mp.get_context("spawn")  # never fork a threaded server
        child_inbox, self._to_child = ctx.Pipe(duplex=False)
        self._from_child, child_outbox = ctx.Pipe(duplex=False)
        self.process = ctx.Process(target=child_main, name="spark-trial-worker", daemon=True,
                                   args=(child_inbox, child_outbox, store_url, artifacts_dir, feed_hz))
        self.process.start()
        child_inbox.close()  # only the child holds these ends: its death closes the pipe (EOF here)
        child_outbox.close()
        self._send_lock = threading.Lock()
        deadline = time.monotonic() + ready_timeout_s
        while (msg := self.recv(0.5)) is None and time.monotonic() < deadline:
            if cancelled():  # the console is stopping: do not keep it waiting for a warm-up
                self.kill()
                raise RuntimeError("the console is shutting down")
        if msg is None or msg[0] != "ready":
            self.kill()
            raise RuntimeError(f"trial worker did not start within {ready_timeout_s:.0f} s ({self.death()})")
        self.pid: int = msg[1]

    @property
    def alive(self) -> bool:
        return self.process.is_alive()

    def send(self, *msg: Any) -> bool:
        with self._send_lock:
            try:
                self._to_child.send(msg)
                return True
            except (BrokenPipeError, OSError):
                return False

    def recv(self, timeout_s: float) -> tuple | None:
        """The next message, None after `timeout_s` of silence, EOF_MSG once the worker is gone."""
        try:
            if not self._from_child.poll(timeout_s):
                return None
            return self._from_child.recv()
        except (EOFError, OSError):
            return EOF_MSG

    def death(self) -> str:
        """How the process ended, for the trial's failure reason."""
        self.process.join(2.0)
        code = self.process.exitcode
        if code is None:
            return "still running"
        if code < 0:
            try:
                return f"killed by {signal.Signals(-code).name}"
            except ValueError:
                return f"killed by signal {-code}"
        return f"exit code {code}"

    def kill(self) -> None:
        if self.process.is_alive():
            self.process.kill()
        self.process.join(5.0)

    def stop(self) -> None:
        self.send("stop")
        self.process.join(5.0)
        self.kill()


# ---------------------------------------------------------------------------------------------------------------
# Worker side


def child_main(inbox, outbox, store_url: str, artifacts_dir: str, feed_hz: float) -> None:
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # Ctrl-C belongs to the console, which stops us in order
    os.environ.setdefault("MUJOCO_GL", "egl")  # before mujoco is imported: cameras render headless
    from spark_core.execution import StepControl
    from spark_core.trace import TraceStore

    lock = threading.Lock()

    def send(*msg: Any) -> None:
        with lock:
            try:
                outbox.send(msg)
            except (BrokenPipeError, OSError):
                os._exit(0)  # the console is gone: nobody is left to report to

    parent = os.getppid()

    def orphan_watch() -> None:  # belt and braces: a pipe end leaked into another process would hide the EOF
        while os.getppid() == parent:
            time.sleep(1.0)
        os._exit(0)

    threading.Thread(target=orphan_watch, name="orphan-watch", daemon=True).start()
    store = TraceStore(store_url, migrate=False)  # the console migrated it before starting workers
    _warm_up()
    current: dict[str, Any] = {"id": None, "control": None}
    send("ready", os.getpid())
    while True:
        try:
            msg = inbox.recv()
        except (EOFError, OSError):
            os._exit(0)  # the console died: its restart marks our trial interrupted, so stop writing now
        if msg[0] == "run":
            _, trial_id, spec, state = msg
            control = StepControl(state["breakpoints"])
            if state["paused"]:
                control.pause()
            if state["aborted"]:
                control.abort()
            current.update(id=trial_id, control=control)
            threading.Thread(target=_job, args=(trial_id, spec, control, store, send, Path(artifacts_dir), feed_hz),
                             name=f"trial-{trial_id}", daemon=True).start()
        elif msg[0] == "control" and msg[1] == current["id"]:
            _, _, action, arg = msg
            c = current["control"]
            c.set_breakpoints(arg) if action == "breakpoints" else getattr(c, action)()
        elif msg[0] == "stop":
            return


def _warm_up() -> None:
    """Import the simulator and planners and load the text encoder now, so the first trial does not pay for it
    (and its 3D feed is not starved while it does)."""
    import spark_core.bench.trial  # noqa: F401 - mujoco, pinocchio, perception, primitives
    from spark_core.perception.text_encoder import SHARED_ENCODER
    from spark_core.sim.tasks import BUILTIN  # noqa: F401

    SHARED_ENCODER.encode(["warm up"])


def _job(trial_id: str, spec: TrialSpec, control, store, send: Callable, artifacts_dir: Path, feed_hz: float) -> None:
    try:
        run_trial(trial_id, spec, control, store, send, artifacts_dir, feed_hz)
    except Exception as e:  # noqa: BLE001 - a crashing trial is recorded, and the worker lives on
        store.update_trial(trial_id, status="done", outcome="failure", success=False, failure="internal",
                           reason=f"internal error: {type(e).__name__}: {e}",
                           protocol={**asdict(spec), "worker_pid": os.getpid(),
                                     "traceback": traceback.format_exc()[-4000:]})
    finally:
        send("done", trial_id)


def run_trial(trial_id: str, spec: TrialSpec, control, store, send: Callable, artifacts_dir: Path,
              feed_hz: float = 30.0) -> None:
    """Plan (unless reference), execute and record one trial; events and the 3D feed go out through `send`."""
    from spark_core.bench.trial import PerceptionConfig, make_resolver
    from spark_core.execution import EventBus, Executor
    from spark_core.execution.primitives import PrimitiveLibrary
    from spark_core.grammar import parse_plan, plan_to_dict, to_yaml
    from spark_core.planning import PlanRequest
    from spark_core.sim.tasks import TASKS
    from spark_core.sim.world import TrajectoryRecorder
    from spark_core.trace.artifacts import detection_images
    from spark_core.trace.record import record_trial

    from .scene_feed import SceneFeed

    if control.aborted:  # cancelled while queued: never starts
        store.update_trial(trial_id, status="done", outcome="aborted", reason="cancelled before it started")
        return
    t0 = time.perf_counter()
    store.update_trial(trial_id, status="running", protocol={**asdict(spec), "worker_pid": os.getpid()})
    send("status", trial_id, "running")
    bus = EventBus(trial_id)
    bus.subscribe(lambda ev: send("event", trial_id, ev.to_dict()))
    task = TASKS[spec.task]
    world = task.make_world(spec.seed, spec.embodiment)
    world.recorder = TrajectoryRecorder()
    episode = None
    if spec.capture:
        from spark_core.sim.capture import EpisodeCapture

        episode = EpisodeCapture(world, clock=bus.now)
        bus.subscribe(episode.on_event)
        world.monitors.append(episode)
    feed = None
    try:
        resolver = make_resolver(world, PerceptionConfig(spec.resolver), spec.seed)
        feed = SceneFeed(world, lambda kind, payload: send(kind, trial_id, payload), feed_hz, resolver).start()
        record = dict(task=task.name, instruction=spec.instruction, seed=spec.seed, planner=spec.planner,
                      resolver=spec.resolver, protocol={**asdict(spec), "worker_pid": os.getpid()})
        cost, usage, plan, library, summary = 0.0, {}, None, None, ""
        if spec.planner == "reference":
            plan = parse_plan(task.reference_plan_text())
        else:
            from spark_core.planning.backends import make_planner
            from spark_core.planning.llm import PlannerUnavailable
            from spark_core.planning.observe import arm_bases, arm_tools, observe
            from spark_core.trace.plan_library import StorePlanLibrary

            try:
                planner = make_planner(spec.planner, spec.model, spec.base_url)
            except (PlannerUnavailable, ValueError) as e:
                store.update_trial(trial_id, status="done", outcome="failure", success=False, failure="planner",
                                   reason=f"planner {spec.planner!r} unavailable: {e}")
                return
            view = observe(spec.instruction, resolver)
            summary = view.summary
            library = StorePlanLibrary(store) if spec.planner != "rules" else None
            examples = library.examples(spec.instruction) if library is not None else ()
            result = planner.plan(PlanRequest(spec.instruction, view, examples, arm_bases(world), arm_tools(world)))
            cost, usage, plan = result.cost_usd, asdict(result.usage), result.plan
            if plan is None:
                record_trial(store, trial_id, **record, plan=None, result=None, success=False,
                             reason=f"no plan: {result.error}", cost_usd=cost, usage=usage,
                             wall_time_s=round(time.perf_counter() - t0, 3))
                return
        store.update_trial(trial_id, plan_text=to_yaml(plan), plan_tree=plan_to_dict(plan))
        ex = Executor(PrimitiveLibrary(world, resolver, seed=spec.seed), resolver, bus=bus, control=control,
                      trial_id=trial_id)
        trial = ex.run(plan)
        world.settle(0.5)
        success = bool(task.success(world)) and trial.outcome == "success"
        artifacts = detection_images(resolver, artifacts_dir / trial_id)
        if episode is not None:
            from spark_core.trace.artifacts import capture_entries

            world.monitors.remove(episode)
            artifacts += capture_entries(episode, artifacts_dir / trial_id)
        record_trial(store, trial_id, **record, plan=plan, result=trial, success=success,
                     groundings=getattr(resolver, "groundings", []), trajectory=world.recorder.rows,
                     scene_states=world.recorder.states, wall_time_s=round(time.perf_counter() - t0, 3),
                     cost_usd=cost, usage=usage, artifacts=artifacts)
        if success and library is not None:
            library.add(spec.instruction, to_yaml(plan), summary, trial_id=trial_id)
    finally:
        if feed is not None:
            feed.stop()
        world.close()
