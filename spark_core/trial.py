"""THE trial pipeline: `run_trial(TrialConfig, sinks, control) -> TrialOutcome`.

The console's workers, `spark run`, `spark bench` (local pool) and Ray tasks all call this one function, so a
task and seed are scored the same way everywhere: the task's predicate within its time limit AND the behavior
tree's success (see `trial_outcome.judge`). What a caller wants to see or keep (a trace store, a live 3D feed,
printed events) is a `TrialSink`; step-through control is a `StepControl`.
"""

from __future__ import annotations

import time
import traceback
from collections.abc import Sequence
from dataclasses import asdict, dataclass, field
from typing import Any, Protocol

from .catalog import (
    DEFAULT_SEGMENTER,
    PLANNERS,
    SEGMENTERS,
    check_embodiment,
    check_planner,
    check_segmenter,
    check_task,
)
from .execution import Event, EventBus, Executor, RecoveryPolicy, StepControl, TrialResult
from .grammar import Plan, parse_plan, to_yaml, validate
from .perception.noisy_segmenter import NoiseModel
from .sim.reclaim import world_closed
from .trial_outcome import TrialOutcome, Verdict, judge


class TrialConfigError(ValueError):
    """A trial that cannot be run as configured; the message names the field and what was expected."""


@dataclass(frozen=True)
class TrialConfig:
    """Everything that decides what a trial does. Picklable (it crosses process and Ray boundaries)."""

    task: str
    instruction: str | None = None  # None: the task's own (LIBERO: the env's)
    planner: str = "reference"  # a catalog planner
    model: str | None = None  # LLM model name (planner default when None)
    base_url: str | None = None  # an ad-hoc LLM URL (CLI only; it gets no key); None: the vendor's
    plan_text: str | None = None  # a plan to run as given (the planner is then not called)
    segmenter: str = DEFAULT_SEGMENTER  # a catalog segmenter (default: the camera-only `learned`)
    cameras: tuple[str, ...] | None = None  # None: the scene's perception cameras
    sam3_model: str | None = None  # SAM3 checkpoint directory (default SPARK_SAM3_MODEL)
    noise: NoiseModel = NoiseModel()  # sim-noisy's failure model
    embodiment: str | None = None  # None: the task's first
    seed: int = 0
    recovery: bool = True  # recovery tiers 1-2 (at most 2 retries per node)
    adaptive: bool = True  # adaptive prompts (label + 3 variants, keep the single confident detection)
    capture: Any = None  # a sim.capture.CaptureConfig: record training-data frames
    time_limit_s: float | None = None  # simulated seconds; None: the task's own `max_sim_s`
    pacing: float | None = None  # x real time (1.0 = real time); None: as fast as the machine goes
    breakpoints: tuple[str, ...] = ()
    start_paused: bool = False
    batch_id: str | None = None
    endpoint: str | None = None  # a named LLM endpoint the operator configured (spark.yaml endpoints:)
    eval_protocol: str | None = None  # a named evaluation configuration (bench.protocols: fair, bddl, ...)

    def check(self) -> TrialConfig:
        """Raise TrialConfigError naming what is wrong; return self. Cheap: builds no world."""
        try:
            task = check_task(self.task)
            check_planner(self.planner)
            check_segmenter(self.segmenter)
            if self.embodiment is not None:
                check_embodiment(self.embodiment)
        except ValueError as e:
            raise TrialConfigError(str(e)) from None
        if self.embodiment is not None and self.embodiment not in task.embodiments:
            raise TrialConfigError(
                f"embodiment: task {self.task!r} runs on {', '.join(task.embodiments)}, not {self.embodiment!r}"
            )
        if self.plan_text is not None:
            plan, issues = validate(self.plan_text)
            if plan is None:
                raise TrialConfigError("plan_text: " + "; ".join(str(i) for i in issues))
        elif self.planner == "reference" and not task.has_reference_plan:
            raise TrialConfigError(
                f"planner: task {self.task!r} has no reference plan; choose a planner "
                f"({', '.join(p for p in PLANNERS if p != 'reference')}) or give a plan"
            )
        if PLANNERS[self.planner].needs_model and not self.model:
            given = " (a given plan runs without calling it: name a model, or leave the planner out)"
            raise TrialConfigError(
                f"model: the {self.planner} planner needs a model name{given if self.plan_text is not None else ''}"
            )
        if self.endpoint is not None:
            from .planning.endpoints import resolve_endpoint

            if self.base_url is not None:
                raise TrialConfigError("base_url: give an endpoint name or a URL, not both")
            try:
                resolve_endpoint(self.endpoint, self.planner, self.model)
            except ValueError as e:
                raise TrialConfigError(str(e)) from None
        if self.segmenter == "sam3":  # the checkpoint must be on this machine: say so before building anything
            import os

            from .perception.sam3_segmenter import DEFAULT_MODEL, Sam3WeightsMissing, locate_checkpoint

            try:
                locate_checkpoint(self.sam3_model or os.environ.get("SPARK_SAM3_MODEL", DEFAULT_MODEL))
            except Sam3WeightsMissing as e:
                raise TrialConfigError(f"segmenter: {e}") from None
        if self.eval_protocol is not None:  # never a privileged figure under the paper's configuration names
            from .bench.protocols import ProtocolError, check_config

            try:
                check_config(self)
            except ProtocolError as e:
                raise TrialConfigError(f"protocol: {e}") from None
        if self.time_limit_s is not None and not 0 < self.time_limit_s <= 3600:
            raise TrialConfigError(f"time_limit_s: expected (0, 3600] simulated seconds, got {self.time_limit_s}")
        if self.pacing is not None and not 0.01 <= self.pacing <= 100:
            raise TrialConfigError(f"pacing: expected [0.01, 100] x real time, got {self.pacing}")
        return self

    def protocol(self, time_limit_s: float) -> dict[str, Any]:
        """The trial's protocol in words: what every figure and record names."""
        seg = SEGMENTERS[self.segmenter]
        planner = (
            "given plan"
            if self.plan_text is not None
            else PLANNERS[self.planner].description
            if PLANNERS[self.planner].offline
            else f"{self.planner} ({self.model or PLANNERS[self.planner].default_model}); two calls: prompt "
            "synthesis (task language + agentview image -> objects to detect"
            + (", 3 alternative prompts each" if self.adaptive else "")
            + "), then the BT call (what perception found, the annotated image, the task language)"
        )
        return {
            "planner": planner,
            "segmenter": self.segmenter,
            "privileged": seg.privileged,
            "segmenter_description": seg.description,
            "cameras": "none" if not seg.cameras else ("+".join(self.cameras) if self.cameras else "scene default"),
            "adaptive_prompts": self.adaptive and seg.cameras,
            "recovery": "tiers 1-2, 2 retries" if self.recovery else "off",
            "embodiment": self.embodiment,
            "seed": self.seed,
            "time_limit_s": time_limit_s,
            "pacing": f"{self.pacing:g}x real time" if self.pacing else "as fast as possible",
            "noise": self.noise.describe() if self.segmenter == "sim-noisy" else None,
            "endpoint": self.endpoint,
            "eval_protocol": self.eval_protocol,
            "success_rule": "the task's predicate within the time limit AND the behavior tree succeeded",
            "wording": (
                "the task's own instruction (official wording; LIBERO: the env's)"
                if self.instruction is None
                else "an instruction given with the trial"
            )
            + ("; plus LIBERO's canonical object names (BDDL categories)" if self.eval_protocol == "bddl" else ""),
        }


class TrialSink(Protocol):
    """Where a running trial's record goes. Every hook is called on the trial's thread; events may also
    arrive from arm threads (concurrent branches)."""

    def on_start(self, ctx: TrialContext) -> None: ...

    def on_plan(self, ctx: TrialContext, plan: Plan | None, planning: dict[str, Any]) -> None: ...

    def on_event(self, event: Event) -> None: ...

    def on_finish(self, ctx: TrialContext | None, outcome: TrialOutcome) -> None: ...


class BaseSink:
    """A sink with every hook a no-op: subclass and override what you need."""

    def on_start(self, ctx: TrialContext) -> None:
        pass

    def on_plan(self, ctx: TrialContext, plan: Plan | None, planning: dict[str, Any]) -> None:
        pass

    def on_event(self, event: Event) -> None:
        pass

    def on_finish(self, ctx: TrialContext | None, outcome: TrialOutcome) -> None:
        pass


@dataclass
class TrialContext:
    """The live parts of a running trial, for sinks (a 3D feed reads `world`; a store reads `resolver`)."""

    trial_id: str
    config: TrialConfig
    task: Any  # sim.tasks.TaskSpec
    instruction: str
    world: Any
    resolver: Any
    bus: EventBus
    protocol: dict[str, Any]
    episode: Any = None  # sim.capture.EpisodeCapture when capturing
    extra: dict[str, Any] = field(default_factory=dict)


class TimedResolver:
    """Counts the wall time spent resolving labels (perception, including the camera frames it draws)."""

    def __init__(self, inner: Any):
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


def phase_split(setup_s: float, run_s: float, world: Any, perception_s: float, planning_s: float) -> dict[str, float]:
    """Where a trial's wall time went: setup (scene build, model loading), rendering (camera frames), perception
    (the rest of label resolution), planning (the planner call), simulation (physics steps) and execution
    (control, IK, trajectories: the rest of the run)."""
    render, sim = world.wall_s["rendering"], world.wall_s["simulation"]
    perception = max(perception_s - render, 0.0)
    execution = max(run_s - render - sim - perception - planning_s, 0.0)
    return {
        k: round(v, 4)
        for k, v in (
            ("setup", setup_s),
            ("perception", perception),
            ("rendering", render),
            ("planning", planning_s),
            ("simulation", sim),
            ("execution", execution),
        )
    }


def _plan(ctx: TrialContext, library: Any) -> tuple[Plan | None, dict[str, Any]]:
    """The plan to run and what planning cost: a given plan, the reference plan, or one planner call on what
    perception found for the instruction's phrases (LLM planners also get the annotated image and few-shot
    examples from the plan library)."""
    cfg = ctx.config
    if cfg.plan_text is not None:
        return parse_plan(cfg.plan_text), {"source": "given"}
    if cfg.planner == "reference":
        return parse_plan(ctx.task.reference_plan_text()), {"source": "reference"}
    from .planning import PlanRequest
    from .planning.backends import make_planner
    from .planning.llm import PlannerUnavailable
    from .planning.observe import arm_bases, arm_tools, image_reference, observe, perceive_for_llm

    t0 = time.perf_counter()
    try:
        planner = make_planner(cfg.planner, cfg.model, cfg.base_url, cfg.endpoint)
    except (ValueError, PlannerUnavailable) as e:  # a missing key or server
        return None, {
            "source": cfg.planner,
            "error": f"planner {cfg.planner!r} unavailable: {e}",
            "latency_s": time.perf_counter() - t0,
        }
    llm = not PLANNERS[cfg.planner].offline
    calls: list[dict[str, Any]] = []
    if llm:  # the paper's loop: synthesis call, every prompt on every camera, the annotated image
        extra: list[str] = []
        if cfg.eval_protocol == "bddl":  # LIBERO's canonical object names, for perception to look for too
            from .bench.protocols import bddl_object_names

            extra = bddl_object_names(cfg.task)
        view, calls = perceive_for_llm(planner, ctx.instruction, ctx.resolver, adaptive=cfg.adaptive, extra=extra)
    else:
        view = observe(ctx.instruction, ctx.resolver)
    if llm and view.image is not None:  # the exact image the BT call gets, kept with the trial's artifacts
        ctx.extra["planner_image"] = (view.image, _planner_camera(ctx))
    examples = library.examples(ctx.instruction) if (llm and library is not None) else ()
    result = planner.plan(PlanRequest(ctx.instruction, view, examples, arm_bases(ctx.world), arm_tools(ctx.world)))
    usage = asdict(result.usage)
    for call in calls:
        usage = {k: usage.get(k, 0) + call["usage"].get(k, 0) for k in usage}
    info = {
        "source": cfg.planner,
        "model": result.detail.get("model"),
        "text": result.text,
        "error": result.error,
        "issues": [str(i) for i in result.issues],
        "understood": result.detail.get("understood"),
        "cost_usd": result.cost_usd + sum(c["cost_usd"] for c in calls),  # both calls, as the paper counts
        "usage": usage,
        "calls": [
            *calls,
            {
                "kind": "behavior_tree",
                "model": result.detail.get("model"),
                "prompt": result.detail.get("prompt"),
                "response": result.text,
                "image": image_reference(view, _planner_camera(ctx)),
                "usage": asdict(result.usage),
                "cost_usd": result.cost_usd,
                "latency_s": round(result.latency_s, 3),
            },
        ],
        "scene_summary": view.summary,
        "latency_s": time.perf_counter() - t0,
        "examples": len(examples),
    }
    return result.plan, info


def _planner_camera(ctx: TrialContext) -> str | None:
    """The camera whose annotated frame the BT call gets (perception's first)."""
    return next(iter(getattr(ctx.resolver, "frames", {}) or {}), None)


def run_trial(
    config: TrialConfig,
    sinks: Sequence[TrialSink] = (),
    control: StepControl | None = None,
    *,
    trial_id: str | None = None,
    library: Any = None,
) -> TrialOutcome:
    """Run one trial end to end and return its outcome; never raises for what happens inside the trial (an
    internal error is the `crashed` verdict, recorded by the sinks). `library`: a plan library whose examples
    LLM planners see and which keeps this trial's plan if it succeeds. Raises TrialConfigError for a bad config."""
    config.check()
    from .sim.tasks import TASKS

    task = TASKS[config.task]
    trial_id = trial_id or f"{task.name}-{config.seed}-{int(time.time() * 1000)}"
    if control is None:  # a caller's own control already carries its state (the console forwards it)
        control = StepControl(config.breakpoints)
        if config.start_paused:
            control.pause()
    t0 = time.perf_counter()
    time_limit_s = config.time_limit_s or task.max_sim_s
    protocol = config.protocol(time_limit_s)

    def unrun(verdict: Verdict, reason: str, failure: str | None = None) -> TrialOutcome:
        """The outcome of a trial that never reached the end of execution."""
        return TrialOutcome(
            trial_id=trial_id,
            task=task.name,
            seed=config.seed,
            instruction=config.instruction or task.instruction,
            verdict=verdict,
            task_success=None,
            tree_status=None,
            failure=failure,
            failed_node=None,
            reason=reason,
            unmet=None,
            sim_time_s=0.0,
            wall_time_s=round(time.perf_counter() - t0, 3),
            protocol=dict(protocol),
        )

    if control.aborted:  # cancelled while queued: never starts
        outcome = unrun(Verdict.ABORTED, "cancelled before it started")
        for sink in sinks:
            sink.on_finish(None, outcome)
        return outcome
    ctx: TrialContext | None = None
    try:
        ctx = _start(config, task, trial_id, protocol, sinks)
        outcome = _run(ctx, sinks, control, library, time_limit_s, t0)
    except Exception as e:
        outcome = unrun(Verdict.CRASHED, f"internal error: {type(e).__name__}: {e}", failure="internal")
        outcome.protocol = {**protocol, "traceback": traceback.format_exc()[-4000:]}
        if ctx is not None:
            outcome.instruction = ctx.instruction
    try:
        for sink in sinks:
            sink.on_finish(ctx, outcome)
    finally:
        if ctx is not None:
            ctx.world.close()
            world_closed()
    if outcome.success and library is not None and not PLANNERS[config.planner].offline and ctx is not None:
        library.add(ctx.instruction, outcome.plan_text, ctx.extra.get("scene_summary", ""), trial_id=trial_id)
    return outcome


def _start(
    config: TrialConfig, task: Any, trial_id: str, protocol: dict[str, Any], sinks: Sequence[TrialSink]
) -> TrialContext:
    from .perception.factory import make_resolver
    from .sim.world import TrajectoryRecorder

    embodiment = config.embodiment or task.embodiments[0]
    protocol["embodiment"] = embodiment
    world = task.make_world(config.seed, embodiment)
    try:
        world.recorder = TrajectoryRecorder()
        bus = EventBus(trial_id, sim_clock=lambda: world.sim_time_s)  # events carry the world's sim time
        resolver = TimedResolver(
            make_resolver(
                world, config.segmenter, config.seed, config.cameras, config.adaptive, config.noise, config.sam3_model
            )
        )
        instruction = config.instruction or getattr(world, "instruction", task.instruction)  # LIBERO: the env's
        ctx = TrialContext(trial_id, config, task, instruction, world, resolver, bus, protocol)
        if config.capture is not None:
            from .sim.capture import EpisodeCapture

            ctx.episode = EpisodeCapture(world, config.capture, clock=bus.now)
            bus.subscribe(ctx.episode.on_event)
            world.monitors.append(ctx.episode)
        for sink in sinks:
            bus.subscribe(sink.on_event)
        for sink in sinks:
            sink.on_start(ctx)
        return ctx
    except BaseException:
        world.close()
        raise


def _run(
    ctx: TrialContext, sinks: Sequence[TrialSink], control: StepControl, library: Any, time_limit_s: float, t0: float
) -> TrialOutcome:
    from .execution.primitives import PrimitiveLibrary
    from .sim.pacing import Pacer, SimTimeLimit

    cfg, world, task = ctx.config, ctx.world, ctx.task
    t_run = time.perf_counter()
    world.wall_s.update(simulation=0.0, rendering=0.0)  # the scene's settling belongs to setup
    sim_start_s = world.sim_time_s
    plan, planning = _plan(ctx, library)
    ctx.extra["scene_summary"] = planning.get("scene_summary", "")
    planning_s = float(planning.get("latency_s", 0.0))
    for sink in sinks:
        sink.on_plan(ctx, plan, planning)
    result: TrialResult | None = None
    limit = SimTimeLimit(sim_start_s, time_limit_s, control.abort)
    if plan is not None:
        monitors = [limit] + ([Pacer(cfg.pacing)] if cfg.pacing else [])
        world.monitors.extend(monitors)
        try:
            recovery = RecoveryPolicy() if cfg.recovery else RecoveryPolicy(max_retries=0)
            executor = Executor(
                PrimitiveLibrary(world, ctx.resolver, seed=cfg.seed),
                ctx.resolver,
                recovery=recovery,
                bus=ctx.bus,
                control=control,
                trial_id=ctx.trial_id,
            )
            result = executor.run(plan)
        finally:
            for m in monitors:
                world.monitors.remove(m)
    used_s = world.sim_time_s - sim_start_s  # the plan's time; the settle below only lets things come to rest
    if result is not None:
        world.settle(0.5)
    t_end = time.perf_counter()
    timed_out = limit.expired or used_s > time_limit_s
    predicate = bool(task.success(world)) if result is not None else None
    task_success = None if predicate is None else (predicate and not timed_out)
    tree_status = result.outcome if result is not None else None
    verdict = judge(
        planned=plan is not None,
        aborted=tree_status == "aborted" and not limit.expired,
        timed_out=timed_out,
        tree_status=tree_status,
        task_success=task_success,
    )
    reason = _reason(verdict, result, planning, used_s, time_limit_s, task)
    referee = getattr(world, "referee", None)  # a task's own bookkeeping (robosuite Wipe's markers)
    if referee is not None and result is not None:
        reason = "; ".join(x for x in (reason, referee.summary) if x)
    failure = (
        result.failure.value
        if result is not None and result.failure
        else "planner"
        if verdict is Verdict.PLANNER_ERROR
        else "timeout"
        if verdict is Verdict.TIMEOUT
        else None
    )
    recorder = world.recorder
    return TrialOutcome(
        trial_id=ctx.trial_id,
        task=task.name,
        seed=cfg.seed,
        instruction=ctx.instruction,
        verdict=verdict,
        task_success=task_success,
        tree_status=tree_status,
        failure=failure,
        failed_node=result.failed_node if result is not None else None,
        reason=reason,
        unmet=task.predicate if verdict in (Verdict.TASK_UNMET, Verdict.TIMEOUT) and not predicate else None,
        sim_time_s=round(world.sim_time_s, 3),
        wall_time_s=round(time.perf_counter() - t0, 3),
        protocol={
            **ctx.protocol,
            "planning": {k: v for k, v in planning.items() if k not in ("text", "scene_summary")},
        },
        retries=sum(r.retries for r in result.nodes.values()) if result is not None else 0,
        events=len(ctx.bus.history),
        trajectory_len=len(recorder.rows) if recorder is not None else 0,
        cost_usd=float(planning.get("cost_usd", 0.0)),
        usage=planning.get("usage", {}),
        plan_text=to_yaml(plan) if plan is not None else "",
        phases_s=phase_split(t_run - t0, t_end - t_run, world, ctx.resolver.wall_s, planning_s),
        result=result,
    )


def _reason(
    verdict: Verdict, result: TrialResult | None, planning: dict[str, Any], used_s: float, limit_s: float, task: Any
) -> str:
    """The outcome in words, for the operator."""
    if verdict is Verdict.PLANNER_ERROR:
        issues = planning.get("issues") or []
        return f"no plan: {planning.get('error') or 'the planner wrote none'}" + (
            f" ({'; '.join(issues[:5])})" if issues else ""
        )
    if verdict is Verdict.TIMEOUT:
        return f"past the task's time limit: {used_s:.1f} s of simulated time, limit {limit_s:.0f} s"
    if verdict is Verdict.TASK_UNMET:
        return f"every node succeeded but the task's success condition is false: {task.predicate}"
    return result.reason if result is not None else ""


__all__ = [
    "BaseSink",
    "TimedResolver",
    "TrialConfig",
    "TrialConfigError",
    "TrialContext",
    "TrialOutcome",
    "TrialSink",
    "Verdict",
    "phase_split",
    "run_trial",
]
