"""`spark run` and `spark plan`: one simulated trial (reference plan, a plan file, or one planner call)."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path


def register(sub) -> None:
    r = sub.add_parser("run", help="run one builtin task in simulation (reference plan or --plan) and print its events")
    r.add_argument("task", help="builtin task name")
    r.add_argument("--seed", type=int, default=0)
    r.add_argument("--embodiment", help="robot set-up: panda, ur10 or bimanual (default: the task's own)")
    r.add_argument("--capture", action="store_true",
                   help="record training-data frames (state, action, agentview + wrist video) for `spark export`")
    r.add_argument("--capture-fps", type=float, default=10.0, help="capture rate, frames per simulated second")
    r.add_argument("--capture-size", default="256x256", help="capture image size WxH (multiples of 8)")
    r.add_argument("--plan", help="plan file to run instead of the task's reference plan")
    r.add_argument("--resolver", choices=["privileged", "sim", "sim-noisy"], help="default: sim")
    r.add_argument("--planner", choices=["reference", "rules", "gemini", "openai"],
                   help="reference: the task's hand-written plan; otherwise plan the instruction from what perception saw")
    r.add_argument("--instruction", help="instruction for --planner (default: the task's own)")
    r.add_argument("--model", help="LLM model name (gemini default: gemini-3.1-pro-preview)")
    r.add_argument("--base-url", help="LLM endpoint (OpenAI-compatible server, or a Gemini proxy)")
    r.add_argument("--plan-library",
                   help="where successful plans are kept and offered to LLM planners as few-shot examples: "
                        "'store' (default: the trace store's plan_library table) or a .jsonl file")
    r.add_argument("--no-plan-library", action="store_true", help="neither use nor grow the plan library")
    r.add_argument("--store", default="sqlite:///var/spark.db", help="trace store (SQLAlchemy URL)")
    r.add_argument("--no-store", action="store_true", help="do not record the trial")

    r.set_defaults(func=_cmd_run)

    pl = sub.add_parser("plan", help="plan an instruction in a task's scene (perception + one planner call) and print the tree")
    pl.add_argument("instruction")
    pl.add_argument("--task", required=True, help="builtin task whose scene to plan in")
    pl.add_argument("--seed", type=int, default=0)
    pl.add_argument("--planner", choices=["rules", "gemini", "openai"], help="default: rules")
    pl.add_argument("--model", help="LLM model name (gemini default: gemini-3.1-pro-preview)")
    pl.add_argument("--base-url", help="LLM endpoint (OpenAI-compatible server, or a Gemini proxy)")
    pl.add_argument("--resolver", choices=["privileged", "sim", "sim-noisy"], help="default: sim")
    pl.set_defaults(func=_cmd_plan)


def _plan_in_scene(task_name: str, instruction: str, seed: int, resolver_kind: str, planner_name: str,
                   model: str | None = None, base_url: str | None = None, library=None, embodiment: str | None = None):
    """Build the task's world, let perception look for the instruction's phrases, and call the planner once."""
    from ..bench.trial import PerceptionConfig, make_resolver
    from ..planning import PlanRequest
    from ..planning.backends import make_planner
    from ..planning.observe import arm_bases, arm_tools, observe
    from ..sim.tasks import TASKS

    planner = make_planner(planner_name, model, base_url)  # fails fast (missing key, server) before any simulation
    task = TASKS[task_name]
    world = task.make_world(seed, embodiment)
    resolver = make_resolver(world, PerceptionConfig(resolver_kind), seed)
    view = observe(instruction, resolver)
    if planner_name != "rules" and getattr(resolver, "frames", None):
        view = _with_annotated_image(view, resolver)
    examples = library.examples(instruction) if library is not None and planner_name != "rules" else ()
    result = planner.plan(PlanRequest(instruction, view, examples, arm_bases(world), arm_tools(world)))
    return task, world, resolver, view, result


def _library(args: argparse.Namespace):
    """The plan library: the trace store's table by default ("store"), or a JSON-lines file given by path."""
    from ..planning.library import PlanLibrary

    if args.plan_library not in (None, "store"):
        return PlanLibrary(args.plan_library, enabled=not args.no_plan_library)
    from pathlib import Path

    from ..trace import TraceStore
    from ..trace.plan_library import StorePlanLibrary

    library = StorePlanLibrary(TraceStore(getattr(args, "store", None) or "sqlite:///var/spark.db"),
                               enabled=not args.no_plan_library)
    legacy = Path("var/plan_library.jsonl")  # where the library lived before the store held it
    if library.enabled and legacy.exists():
        library.import_jsonl(legacy)  # idempotent: rows already in the store are skipped
    return library


def _with_annotated_image(view, resolver):
    """Multimodal planners also get the agentview image with the detections drawn on it."""
    from ..perception.annotate import annotate
    from ..planning import SceneView

    frame = next(iter(resolver.frames.values()))
    return SceneView(view.keypoints, view.summary, annotate(frame, [], view.keypoints))


def _print_plan_result(view, result) -> None:
    print("perception saw:\n" + "\n".join("  " + line for line in view.summary.splitlines()))
    if result.detail.get("understood"):
        print("understood: " + "; ".join(result.detail["understood"]))
    if result.ok:
        from ..grammar import to_yaml

        print(to_yaml(result.plan).rstrip())
    else:
        print(f"no plan: {result.error}", file=sys.stderr)
        for issue in result.issues:
            print(f"  {issue}", file=sys.stderr)


def _cmd_plan(args: argparse.Namespace) -> int:
    """Plan only: perception on the task's scene, one planner call, print the tree."""
    from ..sim.tasks import TASKS

    if args.task not in TASKS:
        print(f"unknown task {args.task!r}; tasks: {', '.join(TASKS)}", file=sys.stderr)
        return 2
    from ..planning.llm import PlannerUnavailable

    try:
        task, world, _, view, result = _plan_in_scene(args.task, args.instruction, args.seed, args.resolver, args.planner,
                                                      args.model, args.base_url)
    except (PlannerUnavailable, ValueError) as e:
        print(f"planner {args.planner!r} unavailable: {e}", file=sys.stderr)
        return 2
    world.close()
    _print_plan_result(view, result)
    if result.usage.input_tokens:
        u = result.usage
        print(f"usage: {u.input_tokens} in, {u.output_tokens} out, {u.reasoning_tokens} reasoning tokens; "
              f"${result.cost_usd:.4f}; {result.latency_s:.1f} s")
    return 0 if result.ok else 1


def _cmd_run(args: argparse.Namespace) -> int:
    """One trial in simulation, printing the live event trail."""
    from ..bench.trial import run_reference_trial
    from ..grammar import validate
    from ..sim.tasks import TASKS

    task = TASKS.get(args.task)
    if task is None:
        print(f"unknown task {args.task!r}; tasks: {', '.join(TASKS)}", file=sys.stderr)
        return 2
    if args.planner != "reference":
        return _run_planned(args)
    plan = None
    if args.plan:
        plan, issues = validate(Path(args.plan).read_bytes())
        if plan is None:
            print(f"{args.plan}: INVALID", *(f"  {i}" for i in issues), sep="\n", file=sys.stderr)
            return 1
    from ..bench.trial import PerceptionConfig

    perception = PerceptionConfig(args.resolver)
    print(f"task {task.name!r}: {task.instruction!r} (seed {args.seed}); resolver: {perception.describe()}")
    capture = None
    if args.capture:
        from ..sim.capture import CaptureConfig

        if args.no_store:
            print("--capture records into the trace store: drop --no-store", file=sys.stderr)
            return 2
        try:
            w, h = (int(v) for v in args.capture_size.lower().split("x"))
            capture = CaptureConfig(fps=args.capture_fps, width=w, height=h)
        except ValueError as e:
            print(f"--capture-size / --capture-fps: {e}", file=sys.stderr)
            return 2
    try:
        out = run_reference_trial(task, args.seed, plan, perception=perception, store=_store(args),
                                  embodiment=args.embodiment, capture=capture)
    except ValueError as e:  # the task does not fit that embodiment
        print(str(e), file=sys.stderr)
        return 2
    for ev in out.result.events:
        detail = " ".join(f"{k}={v}" for k, v in ev.detail.items() if k not in ("arm",))
        print(f"  {ev.t:7.3f}s  {ev.kind:<9} {ev.node_path:<22} {detail}")
    verdict = "SUCCESS" if out.success else f"FAILURE ({out.failure or 'task predicate false'}) {out.reason}"
    print(f"{verdict}: {out.sim_time_s:.1f} s simulated in {out.wall_time_s:.2f} s wall; predicate: {task.predicate}")
    return 0 if out.success else 1


def _run_planned(args: argparse.Namespace) -> int:
    """perception -> one planner call -> execution, headless."""
    import time

    from ..execution import Executor
    from ..execution.primitives import PrimitiveLibrary

    from ..planning.llm import PlannerUnavailable

    instruction = args.instruction or BUILTIN_INSTRUCTION(args.task)
    t0 = time.perf_counter()
    try:
        library = _library(args)
        task, world, resolver, view, result = _plan_in_scene(args.task, instruction, args.seed, args.resolver, args.planner,
                                                             args.model, args.base_url, library, args.embodiment)
    except (PlannerUnavailable, ValueError) as e:
        print(f"planner {args.planner!r} unavailable: {e}", file=sys.stderr)
        return 2
    print(f"task {task.name!r}, instruction {instruction!r} (seed {args.seed}); planner {args.planner}; resolver {args.resolver}")
    _print_plan_result(view, result)
    if not result.ok:
        world.close()
        return 1
    trial = Executor(PrimitiveLibrary(world, resolver, seed=args.seed), resolver).run(result.plan)
    world.settle(0.5)
    for ev in trial.events:
        detail = " ".join(f"{k}={v}" for k, v in ev.detail.items() if k != "arm")
        print(f"  {ev.t:7.3f}s  {ev.kind:<9} {ev.node_path:<22} {detail}")
    success = bool(task.success(world))
    world.close()
    store = _store(args)
    trial_id = f"{task.name}-{args.seed}-{int(time.time() * 1000)}"
    if store is not None:
        from dataclasses import asdict

        from ..trace.record import record_trial

        record_trial(store, trial_id, task=task.name, instruction=instruction,
                     seed=args.seed, planner=args.planner, resolver=args.resolver,
                     protocol={"planner": args.planner, "model": result.detail.get("model"), "resolver": args.resolver,
                               "planner_saw": "instruction + perception of its phrases (no object dictionary)"},
                     plan=result.plan, result=trial, success=success, groundings=getattr(resolver, "groundings", []),
                     wall_time_s=round(time.perf_counter() - t0, 3), cost_usd=result.cost_usd, usage=asdict(result.usage))
    if success:
        from ..grammar import to_yaml

        library.add(instruction, to_yaml(result.plan), view.summary, trial_id=trial_id if store is not None else None)
    verdict = "SUCCESS" if success else f"FAILURE ({trial.failure.value if trial.failure else 'task predicate false'}) {trial.reason}"
    print(f"{verdict}: {trial.sim_time_s:.1f} s simulated, {time.perf_counter() - t0:.1f} s wall; predicate: {task.predicate}")
    return 0 if success else 1


def _store(args: argparse.Namespace):
    if getattr(args, "no_store", False):
        return None
    from ..trace import TraceStore

    return TraceStore(args.store)


def BUILTIN_INSTRUCTION(task: str) -> str:  # noqa: N802 - reads like a constant lookup
    from ..sim.tasks import TASKS

    return TASKS[task].instruction
