"""Trial workers: queued trial specs run in worker threads; each running trial exposes its event bus and
step-through control, and every event is stored and fanned out to live subscribers."""

from __future__ import annotations

import queue
from pathlib import Path
import threading
import time
import traceback
from dataclasses import asdict, dataclass, field
from typing import Callable

from spark_core.execution import EventBus, Executor, StepControl
from spark_core.execution.primitives import PrimitiveLibrary
from spark_core.trace import TraceStore
from spark_core.trace.record import record_trial


@dataclass(frozen=True)
class _Kp:
    position_m: list


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


@dataclass
class Live:
    """A queued or running trial's handles."""

    spec: TrialSpec
    bus: EventBus
    control: StepControl
    subscribers: list[Callable[[dict], None]] = field(default_factory=list)


class TrialRunner:
    def __init__(self, store: TraceStore, workers: int = 2, scene=None, artifacts_dir: str = "var/artifacts"):
        self.store = store
        self.artifacts_dir = Path(artifacts_dir)
        self.scene = scene  # ViserScene mirroring the most recently started trial, or None
        self.queue: queue.Queue[str | None] = queue.Queue()
        self.live: dict[str, Live] = {}
        self.watchers: list[Callable[[dict], None]] = []  # dashboard: every trial's status changes
        self._lock = threading.Lock()
        self.threads = [threading.Thread(target=self._work, name=f"trial-worker-{i}", daemon=True) for i in range(workers)]
        for t in self.threads:
            t.start()

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

    def cancel(self, trial_id: str) -> bool:
        """A queued trial is dropped before it runs (recorded as cancelled); a running one is aborted."""
        with self._lock:
            live = self.live.get(trial_id)
        if live is None:
            return False
        live.control.abort()
        return True

    def submit(self, trial_id: str, spec: TrialSpec, batch_id: str | None = None) -> None:
        bus = EventBus(trial_id)
        live = Live(spec, bus, StepControl(spec.breakpoints))
        if spec.start_paused:
            live.control.pause()  # stops before the first primitive: set breakpoints on the tree, then resume
        bus.subscribe(lambda ev: self._fan_out(trial_id, ev.to_dict()))
        with self._lock:
            self.live[trial_id] = live
        self.store.create_trial(trial_id, status="queued", task=spec.task, instruction=spec.instruction, seed=spec.seed,
                                planner=spec.planner, resolver=spec.resolver, protocol=asdict(spec), batch_id=batch_id)
        self._announce(trial_id, "queued", task=spec.task)
        self.queue.put(trial_id)

    def subscribe(self, trial_id: str, callback: Callable[[dict], None]) -> Callable[[], None]:
        with self._lock:
            live = self.live.get(trial_id)
            if live is None:
                return lambda: None
            live.subscribers.append(callback)
            history = [e.to_dict() for e in live.bus.history]
        for ev in history:
            callback(ev)

        def unsubscribe() -> None:
            with self._lock:
                if callback in live.subscribers:
                    live.subscribers.remove(callback)

        return unsubscribe

    def _fan_out(self, trial_id: str, ev: dict) -> None:
        with self._lock:
            subs = list(self.live[trial_id].subscribers) if trial_id in self.live else []
        for cb in subs:
            cb(ev)

    def shutdown(self) -> None:
        for _ in self.threads:
            self.queue.put(None)

    def _work(self) -> None:
        while (trial_id := self.queue.get()) is not None:
            try:
                self._run(trial_id)
            except Exception as e:  # noqa: BLE001 - a crashing trial must not take the worker down
                self.store.update_trial(trial_id, status="done", outcome="failure", success=False,
                                        reason=f"internal error: {type(e).__name__}: {e}",
                                        protocol={"traceback": traceback.format_exc()[-4000:]})
            finally:
                with self._lock:
                    live = self.live.pop(trial_id, None)
                if live is not None:
                    self._fan_out_closed(live)
                final = self.store.get_trial(trial_id) or {}
                self._announce(trial_id, final.get("status", "done"), success=final.get("success"))

    def _fan_out_closed(self, live: Live) -> None:
        for cb in list(live.subscribers):
            cb({"kind": "closed"})

    def _run(self, trial_id: str) -> None:
        from spark_core.bench.trial import PerceptionConfig, make_resolver
        from spark_core.grammar import parse_plan, plan_to_dict, to_yaml
        from spark_core.planning import PlanRequest
        from spark_core.planning.backends import make_planner
        from spark_core.planning.observe import observe
        from spark_core.sim.tasks import BUILTIN
        from spark_core.sim.world import TrajectoryRecorder

        live = self.live[trial_id]
        spec = live.spec
        if live.control.aborted:  # cancelled while queued: never starts
            self.store.update_trial(trial_id, status="done", outcome="aborted", reason="cancelled before it started")
            return
        t0 = time.perf_counter()
        self.store.update_trial(trial_id, status="running")
        self._announce(trial_id, "running", task=spec.task)
        task = BUILTIN[spec.task]
        world = task.make_world(spec.seed)
        world.recorder = TrajectoryRecorder()
        if self.scene is not None:
            self.scene.show(world)
        resolver = None
        try:
            resolver = make_resolver(world, PerceptionConfig(spec.resolver), spec.seed)
            cost, usage, plan = 0.0, {}, None
            if spec.planner == "reference":
                plan = parse_plan(task.reference_plan_text())
            else:
                from spark_core.planning.llm import PlannerUnavailable

                try:
                    planner = make_planner(spec.planner, spec.model, spec.base_url)
                except (PlannerUnavailable, ValueError) as e:
                    self.store.update_trial(trial_id, status="done", outcome="failure", success=False, failure="planner",
                                            reason=f"planner {spec.planner!r} unavailable: {e}")
                    return
                result = planner.plan(PlanRequest(spec.instruction, observe(spec.instruction, resolver)))
                cost, usage, plan = result.cost_usd, asdict(result.usage), result.plan
                if plan is None:
                    record_trial(self.store, trial_id, task=task.name, instruction=spec.instruction, seed=spec.seed,
                                 planner=spec.planner, resolver=spec.resolver, protocol=asdict(spec), plan=None,
                                 result=None, success=False, reason=f"no plan: {result.error}", cost_usd=cost,
                                 usage=usage, wall_time_s=round(time.perf_counter() - t0, 3))
                    return
            self.store.update_trial(trial_id, plan_text=to_yaml(plan), plan_tree=plan_to_dict(plan))
            ex = Executor(PrimitiveLibrary(world, resolver, seed=spec.seed), resolver, bus=live.bus,
                          control=live.control, trial_id=trial_id)
            trial = ex.run(plan)
            world.settle(0.5)
            success = bool(task.success(world)) and trial.outcome == "success"
            from spark_core.trace.artifacts import detection_images

            artifacts = detection_images(resolver, self.artifacts_dir / trial_id)
            record_trial(self.store, trial_id, task=task.name, instruction=spec.instruction, seed=spec.seed,
                         planner=spec.planner, resolver=spec.resolver, protocol=asdict(spec), plan=plan, result=trial,
                         success=success, groundings=getattr(resolver, "groundings", []), trajectory=world.recorder.rows,
                         wall_time_s=round(time.perf_counter() - t0, 3), cost_usd=cost, usage=usage, artifacts=artifacts)
        finally:
            if self.scene is not None:
                keypoints = {g["label"]: _Kp(g["keypoint"]["position_m"]) for g in getattr(resolver, "groundings", [])
                             if g.get("keypoint")}
                self.scene.markers(keypoints)
                self.scene.detach(world)
            world.close()
