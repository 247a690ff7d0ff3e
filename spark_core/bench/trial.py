"""Run one task trial: build the world from a seed, run a plan through the executor, evaluate success."""

from __future__ import annotations

import time
from pathlib import Path
from dataclasses import dataclass, field, replace
from typing import Any

from ..execution import Executor, RecoveryPolicy, TrialResult
from ..execution.protocols import FailureKind
from ..execution.primitives import PrimitiveLibrary
from ..grammar import Plan, parse_plan
from ..perception.noisy_segmenter import NoiseModel, SimNoisySegmenter
from ..perception.privileged import PrivilegedResolver
from ..perception.resolver import PerceptionResolver
from ..perception.sim_segmenter import SimSegmenter
from ..sim.tasks import TaskSpec

RESOLVERS = ("privileged", "sim", "sim-noisy")


@dataclass(frozen=True)
class PerceptionConfig:
    """Which resolver a trial uses. `privileged` reads simulator state; `sim`/`sim-noisy` go through cameras,
    the segmenter (privileged masks), adaptive prompts and depth lifting."""

    resolver: str = "privileged"
    adaptive: bool = True
    noise: NoiseModel = NoiseModel()
    cameras: tuple[str, ...] | None = None  # None: the scene's own (builtin agentview+side, robosuite agentview+sideview)

    def __post_init__(self):
        if self.resolver not in RESOLVERS:
            raise ValueError(f"unknown resolver {self.resolver!r}; expected one of {', '.join(RESOLVERS)}")

    def describe(self) -> str:
        if self.resolver == "privileged":
            return "PrivilegedResolver (privileged:sim-state, no cameras)"
        cams = ("+".join(self.cameras) if self.cameras else "the scene's default pair (builtin agentview+side, "
                "capbench agentview+sideview, liberopro agentview+frontview)")
        base = (f"{self.resolver} segmenter (privileged masks), cameras {cams} 640x480, "
                f"adaptive prompts {'on (label + 3 variants)' if self.adaptive else 'off'}")
        noise = f", noise: {self.noise.describe()}, misses independent per prompt and per view"
        return base + (noise if self.resolver == "sim-noisy" else "")


@dataclass
class TrialOutcome:
    task: str
    seed: int
    success: bool
    outcome: str
    failure: str | None
    failed_node: str | None
    reason: str
    sim_time_s: float
    wall_time_s: float
    protocol: dict[str, str]
    retries: int = 0
    phases_s: dict[str, float] = field(default_factory=dict)  # wall seconds: perception, planning, execution, ...
    result: TrialResult | None = field(default=None, repr=False)

    def row(self) -> dict[str, Any]:
        return {k: v for k, v in self.__dict__.items() if k != "result"}


def _plan_once(planner: str, instruction: str, world, resolver):
    """Perception looks for the instruction's phrases, then one planner call (timed)."""
    from ..planning.backends import make_planner
    from ..planning.observe import arm_bases, arm_tools, observe
    from ..planning.protocol import PlanRequest

    t0 = time.perf_counter()
    view = observe(instruction, resolver)
    result = make_planner(planner).plan(PlanRequest(instruction, view, (), arm_bases(world), arm_tools(world)))
    return replace(result, latency_s=time.perf_counter() - t0)


def make_resolver(world, config: PerceptionConfig, seed: int):
    if config.resolver == "privileged":
        return PrivilegedResolver(world)
    cameras = config.cameras or world.scene.extra.get("perception_cameras", ("agentview", "side"))
    missing = [c for c in cameras if c not in world.scene.cameras]
    if missing:
        raise ValueError(f"camera(s) {', '.join(missing)} not in this scene; it has {', '.join(world.scene.cameras)}")
    segmenter = SimSegmenter(world.scene.catalog())
    if config.resolver == "sim-noisy":
        segmenter = SimNoisySegmenter(segmenter, config.noise, seed)
    return PerceptionResolver(world, segmenter, cameras=cameras, adaptive=config.adaptive)


class TimedResolver:
    """Counts the wall time spent resolving labels (perception, including the camera frames it draws)."""

    def __init__(self, inner):
        self._inner = inner
        self.wall_s = 0.0

    def resolve(self, label: str):
        t0 = time.perf_counter()
        try:
            return self._inner.resolve(label)
        finally:
            self.wall_s += time.perf_counter() - t0

    def refresh(self) -> None:
        t0 = time.perf_counter()
        try:
            self._inner.refresh()
        finally:
            self.wall_s += time.perf_counter() - t0

    def __getattr__(self, name: str):  # groundings, frames, detections, ...
        return getattr(self._inner, name)


def phase_split(setup_s: float, run_s: float, world, resolver: TimedResolver, planning_s: float = 0.0) -> dict[str, float]:
    """Where a trial's wall time went: setup (scene build, model loading), rendering (camera frames), perception
    (the rest of label resolution), simulation (physics steps), planning (the planner call) and execution
    (control, IK, trajectories: the rest of the run)."""
    render, sim = world.wall_s["rendering"], world.wall_s["simulation"]
    perception = max(resolver.wall_s - render, 0.0)
    execution = max(run_s - render - sim - perception - planning_s, 0.0)
    return {k: round(v, 4) for k, v in (("setup", setup_s), ("perception", perception), ("rendering", render),
                                        ("planning", planning_s), ("simulation", sim), ("execution", execution))}


def run_reference_trial(task: TaskSpec, seed: int, plan: Plan | None = None,
                        recovery: RecoveryPolicy = RecoveryPolicy(),
                        perception: PerceptionConfig = PerceptionConfig(), store=None, capture=None,
                        artifacts_dir: str | Path = "var/artifacts", embodiment: str | None = None,
                        batch_id: str | None = None, planner: str = "reference") -> TrialOutcome:
    """The task's hand-written reference plan (or `plan`), or with `planner` (rules, gemini, openai) one planner
    call on the env's instruction and what perception finds for its phrases, with the configured resolver. A
    plan the planner could not write is a `planner` failure with nothing executed. With a TraceStore,
    the trial (events, groundings, trajectory at the control rate) is recorded under its trial id; with a
    `CaptureConfig` too, training-data frames and videos are written under `artifacts_dir/<trial id>/`."""
    from ..execution import EventBus

    t0 = time.perf_counter()
    trial_id = f"{task.name}-{seed}-{int(time.time() * 1000)}"
    world = task.make_world(seed, embodiment)
    bus = EventBus(f"{task.name}-{seed}")
    episode, artifacts = None, []
    if store is not None:
        from ..sim.world import TrajectoryRecorder

        world.recorder = TrajectoryRecorder()
        if capture is not None:
            from ..sim.capture import EpisodeCapture

            episode = EpisodeCapture(world, capture, clock=bus.now)
            bus.subscribe(episode.on_event)
            world.monitors.append(episode)
    try:
        resolver = TimedResolver(make_resolver(world, perception, seed))
        library = PrimitiveLibrary(world, resolver, seed=seed)
        instruction = getattr(world, "instruction", task.instruction)  # LIBERO: the env's own
        t_run = time.perf_counter()
        sim_start_s = world.sim_time_s
        world.wall_s.update(simulation=0.0, rendering=0.0)  # the scene's settling belongs to setup
        planning_s, planned = 0.0, None
        if planner != "reference" and plan is None:
            planned = _plan_once(planner, instruction, world, resolver)
            planning_s = planned.latency_s
            plan = planned.plan
        else:
            plan = plan or parse_plan(task.reference_plan_text())
        if plan is None:
            result = TrialResult(f"{task.name}-{seed}", "failure", FailureKind.PLANNER, None,
                                 f"the {planner} planner wrote no plan: {planned.error}", {}, [], 0.0, 0.0)
        else:
            result = Executor(library, resolver, recovery=recovery, bus=bus, trial_id=f"{task.name}-{seed}").run(plan)
        used_s = world.sim_time_s - sim_start_s  # the plan's time; the settle below only lets things come to rest
        world.settle(0.5)
        t_end = time.perf_counter()
        success = bool(task.success(world)) and used_s <= task.max_sim_s  # past the horizon the episode is over
        if used_s > task.max_sim_s and result.outcome == "success":
            result.reason = f"past the task's horizon: {used_s:.1f} s of simulated time, limit {task.max_sim_s:.0f} s"
        referee = getattr(world, "referee", None)  # a task's own bookkeeping (robosuite Wipe's markers)
        if referee is not None:
            result.reason = "; ".join(x for x in (result.reason, referee.summary) if x)
        if episode is not None:
            from ..trace.artifacts import capture_entries

            world.monitors.remove(episode)
            artifacts = capture_entries(episode, Path(artifacts_dir) / trial_id)
    finally:
        world.close()
    planner_text = ("reference plan (hand-written)" if planner == "reference"
                    else f"{planner} (one call; saw the instruction and perception of its phrases, no object dictionary)")
    protocol = {"planner": planner_text, "resolver": perception.describe(), "embodiment": embodiment or task.embodiments[0],
                "recovery": "off" if recovery.max_retries == 0 else f"tiers 1-2, {recovery.max_retries} retries"}
    if store is not None:
        from ..trace.record import record_trial

        record_trial(store, trial_id, task=task.name, instruction=instruction,
                     seed=seed, planner=planner, resolver=perception.resolver, protocol=protocol, plan=plan,
                     result=result, success=success, groundings=getattr(resolver, "groundings", []),
                     trajectory=world.recorder.rows, scene_states=world.recorder.states, artifacts=artifacts,
                     wall_time_s=round(time.perf_counter() - t0, 3), batch_id=batch_id)
    return TrialOutcome(
        task=task.name, seed=seed, success=success, outcome=result.outcome,
        failure=result.failure.value if result.failure else None, failed_node=result.failed_node, reason=result.reason,
        sim_time_s=round(world.sim_time_s, 3), wall_time_s=round(time.perf_counter() - t0, 3),
        protocol=protocol,
        retries=sum(r.retries for r in result.nodes.values()),
        phases_s=phase_split(t_run - t0, t_end - t_run, world, resolver, planning_s),
        result=result,
    )
