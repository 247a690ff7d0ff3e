"""`spark run` (one trial through the trial pipeline) and `spark plan` (perception + one planner call)."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from spark_core.catalog import EMBODIMENTS, PLANNERS, SEGMENTERS


def register(sub) -> None:
    r = sub.add_parser("run", help="run one task in simulation and print its events and verdict")
    r.add_argument("task", help="task name (`spark catalog` lists them)")
    r.add_argument("--seed", type=int, default=0)
    r.add_argument("--embodiment", choices=list(EMBODIMENTS), help="robot set-up (default: the task's own)")
    r.add_argument(
        "--capture",
        action="store_true",
        help="record training-data frames (state, action, agentview + wrist video) for `spark export`",
    )
    r.add_argument("--capture-fps", type=float, default=10.0, help="capture rate, frames per simulated second")
    r.add_argument("--capture-size", default="256x256", help="capture image size WxH (multiples of 8)")
    r.add_argument("--plan", help="plan file to run instead of the task's reference plan or a planner's")
    r.add_argument(
        "--segmenter", choices=list(SEGMENTERS), help="perception backend (default: learned; sim is the oracle)"
    )
    r.add_argument("--sam3-model", help="SAM3 checkpoint directory for --segmenter sam3 (default: SPARK_SAM3_MODEL)")
    r.add_argument(
        "--planner",
        choices=list(PLANNERS),
        help="reference: the task's hand-written plan; otherwise plan the instruction from what perception saw",
    )
    r.add_argument("--instruction", help="instruction for --planner (default: the task's own)")
    r.add_argument("--model", help="LLM model name (gemini default: gemini-3.1-pro-preview)")
    r.add_argument("--base-url", help="an ad-hoc LLM URL (a local OpenAI-compatible server); it gets no key")
    r.add_argument("--endpoint", help="a named LLM endpoint from spark.yaml `endpoints:` (with its key)")
    r.add_argument("--no-recovery", action="store_true", help="no retries (recovery tiers off)")
    r.add_argument("--no-adaptive", action="store_true", help="one prompt per label (no adaptive prompts)")
    r.add_argument("--time-limit", type=float, help="simulated seconds (default: the task's own)")
    r.add_argument(
        "--pacing", type=float, help="run at this factor of real time (1 = real time; default: as fast as possible)"
    )
    r.add_argument(
        "--plan-library",
        help="where successful plans are kept and offered to LLM planners as few-shot examples: "
        "'store' (default: the trace store's plan_library table) or a .jsonl file",
    )
    r.add_argument("--no-plan-library", action="store_true", help="neither use nor grow the plan library")
    r.add_argument("--store", default="sqlite:///var/spark.db", help="trace store (SQLAlchemy URL)")
    r.add_argument("--no-store", action="store_true", help="do not record the trial")
    r.set_defaults(func=_cmd_run)

    pl = sub.add_parser(
        "plan", help="plan an instruction in a task's scene (perception + one planner call) and print the tree"
    )
    pl.add_argument("instruction")
    pl.add_argument("--task", required=True, help="task whose scene to plan in")
    pl.add_argument("--seed", type=int, default=0)
    pl.add_argument("--planner", choices=[p for p in PLANNERS if p != "reference"], help="default: rules")
    pl.add_argument("--model", help="LLM model name (gemini default: gemini-3.1-pro-preview)")
    pl.add_argument("--base-url", help="an ad-hoc LLM URL (a local OpenAI-compatible server); it gets no key")
    pl.add_argument("--endpoint", help="a named LLM endpoint from spark.yaml `endpoints:` (with its key)")
    pl.add_argument(
        "--segmenter", choices=list(SEGMENTERS), help="perception backend (default: learned; sim is the oracle)"
    )
    pl.add_argument("--sam3-model", help="SAM3 checkpoint directory for --segmenter sam3 (default: SPARK_SAM3_MODEL)")
    pl.set_defaults(func=_cmd_plan)


def _library(args: argparse.Namespace):
    """The plan library: the trace store's table by default ("store"), or a JSON-lines file given by path."""
    from spark_core.planning.plan_library import PlanLibrary

    if args.plan_library not in (None, "store"):
        return PlanLibrary(args.plan_library, enabled=not args.no_plan_library)
    from spark_core.trace import TraceStore
    from spark_core.trace.library_table import StorePlanLibrary

    library = StorePlanLibrary(
        TraceStore(getattr(args, "store", None) or "sqlite:///var/spark.db"), enabled=not args.no_plan_library
    )
    legacy = Path("var/plan_library.jsonl")  # where the library lived before the store held it
    if library.enabled and legacy.exists():
        library.import_jsonl(legacy)  # idempotent: rows already in the store are skipped
    return library


def _cmd_plan(args: argparse.Namespace) -> int:
    """Plan only: perception on the task's scene, one planner call, print the tree."""
    from spark_core.catalog import CatalogError, check_task
    from spark_core.perception.factory import make_resolver
    from spark_core.planning import PlanRequest
    from spark_core.planning.backends import make_planner
    from spark_core.planning.llm import PlannerUnavailable
    from spark_core.planning.observe import arm_bases, arm_tools, observe, perceive_for_llm

    try:
        task = check_task(args.task)
        planner = make_planner(
            args.planner, args.model, args.base_url, args.endpoint
        )  # fails fast, before any simulation
    except CatalogError as e:
        print(str(e), file=sys.stderr)
        return 2
    except (ValueError, PlannerUnavailable) as e:  # a missing key or server
        print(f"planner {args.planner!r} unavailable: {e}", file=sys.stderr)
        return 2
    world = task.make_world(args.seed)
    try:
        resolver = make_resolver(world, args.segmenter, args.seed, sam3_model=args.sam3_model)
        calls: list[dict] = []
        if args.planner == "rules":
            view = observe(args.instruction, resolver)
        else:  # the paper's loop: the prompt-synthesis call, then perception, then the BT call
            view, calls = perceive_for_llm(planner, args.instruction, resolver, adaptive=True)
        result = planner.plan(PlanRequest(args.instruction, view, (), arm_bases(world), arm_tools(world)))
    finally:
        world.close()
    for call in calls:  # the synthesis call: what it asked perception to look for
        if "error" in call:
            print(f"prompt synthesis failed ({call['error']}); perception used its synonym table")
        else:
            print(f"prompt synthesis: objects {', '.join(call.get('objects', [])) or 'none'}")
            for obj, prompts in call.get("variants", {}).items():
                print(f"  {obj}: {', '.join(prompts)}")
    print("perception saw:\n" + "\n".join("  " + line for line in view.summary.splitlines()))
    if result.detail.get("understood"):
        print("understood: " + "; ".join(result.detail["understood"]))
    if result.plan is not None:
        from spark_core.grammar import to_yaml

        print(to_yaml(result.plan).rstrip())
    else:
        print(f"no plan: {result.error}", file=sys.stderr)
        for issue in result.issues:
            print(f"  {issue}", file=sys.stderr)
    if result.usage.input_tokens:
        u = result.usage
        print(
            f"usage: {u.input_tokens} in, {u.output_tokens} out, {u.reasoning_tokens} reasoning tokens; "
            f"${result.cost_usd:.4f}; {result.latency_s:.1f} s"
        )
    if calls:  # the trial's cost counts both calls, as the paper does
        total = result.cost_usd + sum(c.get("cost_usd", 0.0) for c in calls)
        print(f"cost of both calls (synthesis + BT): ${total:.4f}")
    return 0 if result.ok else 1


class _PrintSink:
    """Prints the plan and every event as it happens."""

    def on_start(self, ctx) -> None:
        print(
            f"task {ctx.task.name!r}: {ctx.instruction!r} (seed {ctx.config.seed}); planner {ctx.config.planner}; "
            f"segmenter {ctx.config.segmenter}{' (PRIVILEGED)' if ctx.protocol['privileged'] else ''}",
            flush=True,
        )

    def on_plan(self, ctx, plan, planning) -> None:
        if planning.get("scene_summary"):
            print("perception saw:\n" + "\n".join("  " + line for line in planning["scene_summary"].splitlines()))
        if planning.get("understood"):
            print("understood: " + "; ".join(planning["understood"]))
        if plan is None:
            print(f"no plan: {planning.get('error')}", file=sys.stderr)
            for issue in planning.get("issues", []):
                print(f"  {issue}", file=sys.stderr)
        elif planning.get("source") not in ("reference", "given"):
            from spark_core.grammar import to_yaml

            print(to_yaml(plan).rstrip())

    def on_event(self, ev) -> None:
        detail = " ".join(f"{k}={v}" for k, v in ev.detail.items() if k != "arm")
        print(f"  {ev.t:7.3f}s  {ev.kind:<9} {ev.node_path:<22} {detail}", flush=True)

    def on_finish(self, ctx, outcome) -> None:
        pass


def _cmd_run(args: argparse.Namespace) -> int:
    """One trial through the trial pipeline; exits 0 only on the `success` verdict."""
    from spark_core.trial import TrialConfig, TrialConfigError, run_trial

    plan_text = None
    if args.plan:
        try:
            plan_text = Path(args.plan).read_text(encoding="utf-8")
        except OSError as e:
            print(f"--plan: {e}", file=sys.stderr)
            return 2
    capture = None
    if args.capture:
        from spark_core.sim.capture import CaptureConfig

        if args.no_store:
            print("--capture records into the trace store: drop --no-store", file=sys.stderr)
            return 2
        try:
            w, h = (int(v) for v in args.capture_size.lower().split("x"))
            capture = CaptureConfig(fps=args.capture_fps, width=w, height=h)
        except ValueError as e:
            print(f"--capture-size / --capture-fps: {e}", file=sys.stderr)
            return 2
    config = TrialConfig(
        args.task,
        instruction=args.instruction,
        planner=args.planner,
        model=args.model,
        base_url=args.base_url,
        plan_text=plan_text,
        segmenter=args.segmenter,
        sam3_model=args.sam3_model,
        endpoint=args.endpoint,
        embodiment=args.embodiment,
        seed=args.seed,
        recovery=not args.no_recovery,
        adaptive=not args.no_adaptive,
        capture=capture,
        time_limit_s=args.time_limit,
        pacing=args.pacing,
    )
    try:
        config.check()
    except TrialConfigError as e:
        print(str(e), file=sys.stderr)
        return 2
    sinks: list = [_PrintSink()]
    library = None
    if not args.no_store:
        from spark_core.trace import TraceStore
        from spark_core.trace.sink import StoreSink

        sinks.append(StoreSink(TraceStore(args.store)))
    if not PLANNERS[config.planner].offline and plan_text is None:
        library = _library(args)
    out = run_trial(config, sinks, library=library)
    limit_s = out.protocol.get("time_limit_s")
    print(
        f"verdict: {out.verdict.value}; task predicate: {_yes_no(out.task_success)} ({limit_s} s limit); "
        f"behavior tree: {out.tree_status or 'not run'}"
    )
    if out.reason:
        print(f"reason: {out.reason}")
    if out.unmet:
        print(f"unmet condition: {out.unmet}")
    print(
        f"{out.sim_time_s:.1f} s simulated in {out.wall_time_s:.2f} s wall; trial {out.trial_id}"
        + ("" if args.no_store else f" recorded in {args.store}")
    )
    return 0 if out.success else 1


def _yes_no(value: bool | None) -> str:
    return {True: "true", False: "false", None: "not judged"}[value]
