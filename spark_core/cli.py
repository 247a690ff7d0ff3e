"""The `spark` command."""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

from . import __version__


def _cmd_grammar(args: argparse.Namespace) -> int:
    from .grammar import plan_json_schema
    from .grammar.reference import markdown, table

    if args.format == "md":
        print(markdown())
    elif args.format == "json-schema":
        print(json.dumps(plan_json_schema(), indent=2))
    else:
        print(table())
    return 0


def _cmd_validate(args: argparse.Namespace) -> int:
    from .grammar import to_yaml, validate

    status = 0
    for name in args.plans:
        path = Path(name)
        try:
            data = sys.stdin.buffer.read() if name == "-" else path.read_bytes()
        except OSError as e:
            print(f"{name}: cannot read: {e.strerror}", file=sys.stderr)
            status = 1
            continue
        plan, issues = validate(data)
        if plan is None:
            status = 1
            print(f"{name}: INVALID ({len(issues)} error{'s' if len(issues) != 1 else ''})")
            for issue in issues:
                print(f"  {issue}")
        else:
            n = len(plan.primitives())
            print(f"{name}: ok - {plan.task!r}: {n} primitive{'s' if n != 1 else ''}, labels {', '.join(plan.labels()) or '-'}")
            if args.canonical:
                print(to_yaml(plan))
    return status


def _simple_benches(args: argparse.Namespace) -> dict:
    """suite -> (BENCHMARKS.md title, run(), section(result, command)); imports stay lazy."""
    from .bench import control_bench

    def server_bench(module: str):
        import importlib

        return importlib.import_module(f"server.{module}")

    return {
        "ik": ("IK (Panda, pinocchio)", lambda: control_bench.ik_benchmark(args.targets), control_bench.ik_section),
        "speed": ("simulation speed", control_bench.speed_benchmark, control_bench.speed_section),
        "api": ("console API latency", lambda: server_bench("bench_api").run(args.store_size),
                lambda r, c: server_bench("bench_api").section(r, c)),
        "latency": ("console event latency (executor to browser)", lambda: server_bench("bench_latency").run(),
                    lambda r, c: server_bench("bench_latency").section(r, c)),
        "viser": ("live 3D view frame rate", lambda: server_bench("bench_viser").run(),
                  lambda r, c: server_bench("bench_viser").section(r, c)),
    }


def _cmd_bench(args: argparse.Namespace) -> int:
    from .bench import reference_suite
    from .bench.report import write_section

    command = "spark bench " + " ".join(sys.argv[2:]) if sys.argv[1:2] == ["bench"] else "spark bench " + args.suite
    simple = _simple_benches(args)  # suites whose result is one dict: print it, then its section
    if args.suite in simple:
        title, run, section = simple[args.suite]
        r = run()
        print(json.dumps(r, indent=2))
        body = section(r, command)
    elif args.suite == "paraphrases":
        from .bench import paraphrases

        rows, errors = paraphrases.run(args.seed)
        for r in rows:
            print(f"{'ok ' if r['success'] else 'FAIL'} {r['task']:<16} {r['instruction']!r} {'' if r['success'] else r['outcome']}")
        for e in errors:
            print(f"{'refused' if e['refused'] else 'PLANNED'} {e['instruction']!r}: {e['error']}")
        title, body = "rules planner on paraphrased instructions", paraphrases.section(rows, errors, command)
        print(body)
    elif args.suite == "grounding":
        from .bench import grounding

        rows = grounding.run()
        for r in rows:
            err = f"{100 * r['keypoint_error_m']:.2f} cm" if r["keypoint_error_m"] is not None else "-"
            print(f"{'ok ' if r['correct'] else 'MISS'} {r['scene']:<22} {r['prompt']!r:<36} -> {r['got']} ({err})")
        title, body = "perception grounding (sim segmenter)", grounding.section(rows, command)
        print(body)
    else:
        from .sim.tasks import BUILTIN

        from .bench.trial import PerceptionConfig
        from .execution import RecoveryPolicy
        from .perception.noisy_segmenter import NoiseModel

        if args.planner != "reference":
            print("only --planner reference is available until the planning backends land", file=sys.stderr)
            return 2
        perception = PerceptionConfig(args.resolver, not args.no_adaptive, NoiseModel(miss_rate=args.miss_rate),
                                      tuple(args.cameras))
        recovery = RecoveryPolicy(max_retries=0) if args.no_recovery else RecoveryPolicy()
        tasks = args.tasks or list(BUILTIN)
        unknown = [t for t in tasks if t not in BUILTIN]
        if unknown:
            print(f"unknown task(s): {', '.join(unknown)}; builtin tasks: {', '.join(BUILTIN)}", file=sys.stderr)
            return 2
        total = len(tasks) * args.trials
        done = [0]

        def progress(row: dict) -> None:
            done[0] += 1
            mark = "ok " if row["success"] else "FAIL"
            print(f"[{done[0]:>4}/{total}] {mark} {row['task']} seed {row['seed']} "
                  f"({row['sim_time_s']:.1f} s sim, {row['wall_time_s']:.2f} s wall) {row['reason'][:100]}", flush=True)

        rows = reference_suite.run(tasks, args.trials, args.seed, args.workers, progress, perception, recovery)
        print(reference_suite.table(rows))
        title = args.title or f"builtin reference plans ({args.resolver} resolver)"
        body = reference_suite.section(rows, command, perception, recovery)
        if args.json:
            Path(args.json).write_text(json.dumps(rows, indent=1))
    if args.write:
        write_section(Path(args.write), title, body)
        print(f"wrote section {title!r} of {args.write}")
    return 0


def _plan_in_scene(task_name: str, instruction: str, seed: int, resolver_kind: str, planner_name: str,
                   model: str | None = None, base_url: str | None = None, library=None):
    """Build the task's world, let perception look for the instruction's phrases, and call the planner once."""
    from .bench.trial import PerceptionConfig, make_resolver
    from .planning import PlanRequest
    from .planning.backends import make_planner
    from .planning.observe import observe
    from .sim.tasks import BUILTIN

    planner = make_planner(planner_name, model, base_url)  # fails fast (missing key, server) before any simulation
    task = BUILTIN[task_name]
    world = task.make_world(seed)
    resolver = make_resolver(world, PerceptionConfig(resolver_kind), seed)
    view = observe(instruction, resolver)
    if planner_name != "rules" and getattr(resolver, "frames", None):
        view = _with_annotated_image(view, resolver)
    examples = library.examples(instruction) if library is not None and planner_name != "rules" else ()
    result = planner.plan(PlanRequest(instruction, view, examples))
    return task, world, resolver, view, result


def _library(args: argparse.Namespace):
    """The plan library: the trace store's table by default ("store"), or a JSON-lines file given by path."""
    from .planning.library import PlanLibrary

    if args.plan_library not in (None, "store"):
        return PlanLibrary(args.plan_library, enabled=not args.no_plan_library)
    from pathlib import Path

    from .trace import TraceStore
    from .trace.plan_library import StorePlanLibrary

    library = StorePlanLibrary(TraceStore(getattr(args, "store", None) or "sqlite:///var/spark.db"),
                               enabled=not args.no_plan_library)
    legacy = Path("var/plan_library.jsonl")  # where the library lived before the store held it
    if library.enabled and legacy.exists():
        library.import_jsonl(legacy)  # idempotent: rows already in the store are skipped
    return library


def _with_annotated_image(view, resolver):
    """Multimodal planners also get the agentview image with the detections drawn on it."""
    from .perception.annotate import annotate
    from .planning import SceneView

    frame = next(iter(resolver.frames.values()))
    return SceneView(view.keypoints, view.summary, annotate(frame, [], view.keypoints))


def _print_plan_result(view, result) -> None:
    print("perception saw:\n" + "\n".join("  " + line for line in view.summary.splitlines()))
    if result.detail.get("understood"):
        print("understood: " + "; ".join(result.detail["understood"]))
    if result.ok:
        from .grammar import to_yaml

        print(to_yaml(result.plan).rstrip())
    else:
        print(f"no plan: {result.error}", file=sys.stderr)
        for issue in result.issues:
            print(f"  {issue}", file=sys.stderr)


def _cmd_plan(args: argparse.Namespace) -> int:
    """Plan only: perception on the task's scene, one planner call, print the tree."""
    from .sim.tasks import BUILTIN

    if args.task not in BUILTIN:
        print(f"unknown task {args.task!r}; builtin tasks: {', '.join(BUILTIN)}", file=sys.stderr)
        return 2
    from .planning.llm import PlannerUnavailable

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
    from .bench.trial import run_reference_trial
    from .grammar import validate
    from .sim.tasks import BUILTIN

    task = BUILTIN.get(args.task)
    if task is None:
        print(f"unknown task {args.task!r}; builtin tasks: {', '.join(BUILTIN)}", file=sys.stderr)
        return 2
    if args.planner != "reference":
        return _run_planned(args)
    plan = None
    if args.plan:
        plan, issues = validate(Path(args.plan).read_bytes())
        if plan is None:
            print(f"{args.plan}: INVALID", *(f"  {i}" for i in issues), sep="\n", file=sys.stderr)
            return 1
    from .bench.trial import PerceptionConfig

    perception = PerceptionConfig(args.resolver)
    print(f"task {task.name!r}: {task.instruction!r} (seed {args.seed}); resolver: {perception.describe()}")
    out = run_reference_trial(task, args.seed, plan, perception=perception, store=_store(args))
    for ev in out.result.events:
        detail = " ".join(f"{k}={v}" for k, v in ev.detail.items() if k not in ("arm",))
        print(f"  {ev.t:7.3f}s  {ev.kind:<9} {ev.node_path:<22} {detail}")
    verdict = "SUCCESS" if out.success else f"FAILURE ({out.failure or 'task predicate false'}) {out.reason}"
    print(f"{verdict}: {out.sim_time_s:.1f} s simulated in {out.wall_time_s:.2f} s wall; predicate: {task.predicate}")
    return 0 if out.success else 1


def _run_planned(args: argparse.Namespace) -> int:
    """perception -> one planner call -> execution, headless."""
    import time

    from .execution import Executor
    from .execution.primitives import PrimitiveLibrary

    from .planning.llm import PlannerUnavailable

    instruction = args.instruction or BUILTIN_INSTRUCTION(args.task)
    t0 = time.perf_counter()
    try:
        library = _library(args)
        task, world, resolver, view, result = _plan_in_scene(args.task, instruction, args.seed, args.resolver, args.planner,
                                                             args.model, args.base_url, library)
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

        from .trace.record import record_trial

        record_trial(store, trial_id, task=task.name, instruction=instruction,
                     seed=args.seed, planner=args.planner, resolver=args.resolver,
                     protocol={"planner": args.planner, "model": result.detail.get("model"), "resolver": args.resolver,
                               "planner_saw": "instruction + perception of its phrases (no object dictionary)"},
                     plan=result.plan, result=trial, success=success, groundings=getattr(resolver, "groundings", []),
                     wall_time_s=round(time.perf_counter() - t0, 3), cost_usd=result.cost_usd, usage=asdict(result.usage))
    if success:
        from .grammar import to_yaml

        library.add(instruction, to_yaml(result.plan), view.summary, trial_id=trial_id if store is not None else None)
    verdict = "SUCCESS" if success else f"FAILURE ({trial.failure.value if trial.failure else 'task predicate false'}) {trial.reason}"
    print(f"{verdict}: {trial.sim_time_s:.1f} s simulated, {time.perf_counter() - t0:.1f} s wall; predicate: {task.predicate}")
    return 0 if success else 1


def _cmd_serve(args: argparse.Namespace) -> int:
    """The console's API server (uvicorn) on the offline defaults."""
    import os

    import uvicorn

    from server.app import create_app
    from server.settings import Settings

    from dataclasses import replace

    base = Settings.from_env()
    settings = replace(base, host=args.host or base.host, port=args.port or base.port, store_url=args.store or base.store_url,
                       workers=args.workers or base.workers, spawn_workers_at_start=True)
    if not settings.loopback and not settings.api_token:
        print(f"refusing to serve on {settings.host} without SPARK_API_TOKEN (mutating calls would be open)", file=sys.stderr)
        return 2
    os.environ.setdefault("MUJOCO_GL", "egl")
    print(f"SPARK console API on http://{settings.host}:{settings.port} (docs at /docs); store {settings.store_url}")
    uvicorn.run(create_app(settings), host=settings.host, port=settings.port, log_level="info")
    return 0


def _store(args: argparse.Namespace):
    if getattr(args, "no_store", False):
        return None
    from .trace import TraceStore

    return TraceStore(args.store)


def _cmd_trials(args: argparse.Namespace) -> int:
    """List recorded trials, or show one as JSON."""
    from .trace import TraceStore

    store = TraceStore(args.store)
    if args.id:
        trial = store.get_trial(args.id)
        if trial is None:
            print(f"no trial {args.id!r} in {args.store}", file=sys.stderr)
            return 1
        print(json.dumps(trial, indent=1, default=str))
        return 0
    total, rows = store.list_trials(task=args.task, limit=args.limit)
    print(f"{total} trial(s) in {args.store}; newest {len(rows)}:")
    for r in rows:
        ok = {True: "ok  ", False: "FAIL", None: "-   "}[r["success"]]
        print(f"  {r['created_at'][:19]}  {ok} {r['id']:<34} {r['task']:<16} {r['planner']:<9} {r['instruction'][:50]!r}")
    return 0


def BUILTIN_INSTRUCTION(task: str) -> str:  # noqa: N802 - reads like a constant lookup
    from .sim.tasks import BUILTIN

    return BUILTIN[task].instruction


def _date(text: str):
    from datetime import datetime, timezone

    try:
        return datetime.strptime(text, "%Y-%m-%d").replace(tzinfo=timezone.utc)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a date YYYY-MM-DD, got {text!r}") from None


def _cmd_export(args: argparse.Namespace) -> int:
    """Recorded trials (captured with frames) -> a LeRobot v3.0 dataset with SPARK's per-frame labels."""
    from .sim.tasks import BUILTIN
    from .trace import TraceStore
    from .trace.lerobot import ExportError, ExportFilter, export_lerobot

    tasks = tuple(args.task) or (tuple(BUILTIN) if args.suite == "builtin" else ())
    flt = ExportFilter(tasks=tasks, trial_ids=tuple(args.trial), batch=args.batch,
                       success_only=not args.include_failures, since=args.since, until=args.until)
    try:
        r = export_lerobot(TraceStore(args.store), args.out, flt)
    except ExportError as e:
        print(f"export failed: {e}", file=sys.stderr)
        return 1
    print(f"{r.episodes} episodes, {r.frames} frames -> {r.out_dir} ({r.bytes_on_disk / 1e6:.1f} MB, "
          f"{r.data_files} data file(s), {r.video_files} video file(s)) in {r.wall_time_s:.1f} s")
    for s in r.skipped:
        print(f"  skipped {s['id']}: {s['reason']}")
    return 0


def build_parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(prog="spark", description="SPARK: typed behavior trees over anchored keypoints.")
    p.add_argument("--version", action="version", version=f"spark {__version__}")
    sub = p.add_subparsers(dest="command", metavar="COMMAND")

    g = sub.add_parser("grammar", help="print the primitive grammar (generated from the registry)")
    g.add_argument("--format", choices=["table", "md", "json-schema"], default="table")
    g.set_defaults(func=_cmd_grammar)

    v = sub.add_parser("validate", help="parse and type-check plan files (YAML or JSON); exit 1 listing every error")
    v.add_argument("plans", nargs="+", metavar="PLAN", help="plan file, or - for stdin")
    v.add_argument("--canonical", action="store_true", help="print the canonical YAML of valid plans")
    v.set_defaults(func=_cmd_validate)

    r = sub.add_parser("run", help="run one builtin task in simulation (reference plan or --plan) and print its events")
    r.add_argument("task", help="builtin task name")
    r.add_argument("--seed", type=int, default=0)
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

    sv = sub.add_parser("serve", help="start the console server (REST API + live events) on 127.0.0.1:8000")
    sv.add_argument("--host")
    sv.add_argument("--port", type=int)
    sv.add_argument("--store", help="trace store URL (default sqlite:///var/spark.db)")
    sv.add_argument("--workers", type=int, help="trials run concurrently (default 2)")
    sv.set_defaults(func=_cmd_serve)

    ex = sub.add_parser("export", help="export recorded trials as a training dataset (LeRobot v3.0)")
    ex.add_argument("--format", choices=["lerobot"], default="lerobot")
    ex.add_argument("--out", required=True, help="new (or empty) directory for the dataset")
    ex.add_argument("--store", default="sqlite:///var/spark.db", help="trace store (SQLAlchemy URL)")
    ex.add_argument("--suite", choices=["builtin"], help="only trials of this suite's tasks")
    ex.add_argument("--task", nargs="*", default=[], help="only these tasks")
    ex.add_argument("--trial", nargs="*", default=[], help="only these trial ids")
    ex.add_argument("--batch", help="only this batch's trials")
    ex.add_argument("--since", type=_date, help="recorded on or after this date (YYYY-MM-DD)")
    ex.add_argument("--until", type=_date, help="recorded before this date (YYYY-MM-DD)")
    ex.add_argument("--include-failures", action="store_true",
                    help="also failed trials (default: verified successes only, i.e. clean demonstrations)")
    ex.set_defaults(func=_cmd_export)

    tr = sub.add_parser("trials", help="list recorded trials (or print one with --id)")
    tr.add_argument("--store", default="sqlite:///var/spark.db")
    tr.add_argument("--task")
    tr.add_argument("--limit", type=int, default=20)
    tr.add_argument("--id", help="print this trial's full record as JSON")
    tr.set_defaults(func=_cmd_trials)
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

    b = sub.add_parser("bench", help="run a benchmark and optionally write its section of BENCHMARKS.md")
    b.add_argument("suite", choices=["builtin", "grounding", "paraphrases", "ik", "speed", "api", "latency", "viser"])
    b.add_argument("--trials", type=int, default=20, help="trials (seeds) per task")
    b.add_argument("--tasks", nargs="*", help="subset of task names")
    b.add_argument("--seed", type=int, default=0, help="first seed")
    b.add_argument("--planner", default="reference", help="reference (hand-written plans)")
    b.add_argument("--resolver", default="privileged", choices=["privileged", "sim", "sim-noisy"],
                   help="privileged (simulator state) or a segmenter pipeline (cameras + masks + depth)")
    b.add_argument("--no-adaptive", action="store_true", help="one prompt per label (no adaptive self-consistency)")
    b.add_argument("--no-recovery", action="store_true", help="no retries (recovery tiers off)")
    b.add_argument("--miss-rate", type=float, default=0.2, help="sim-noisy detector miss rate")
    b.add_argument("--cameras", nargs="+", default=["agentview", "side"], help="cameras the resolver fuses")
    b.add_argument("--title", help="BENCHMARKS.md section title (default derived from the resolver)")
    b.add_argument("--workers", type=int, default=1, help="local worker processes")
    b.add_argument("--targets", type=int, default=200, help="IK targets (ik suite)")
    b.add_argument("--store-size", type=int, default=10_000, help="trials in the trace store (api suite)")
    b.add_argument("--write", metavar="BENCHMARKS.md", help="replace this benchmark's section in the file")
    b.add_argument("--json", metavar="FILE", help="also write per-trial rows as JSON")
    b.set_defaults(func=_cmd_bench)
    return p


def _apply_config(args: argparse.Namespace) -> None:
    """Settings from spark.yaml / SPARK_CONFIG fill in whatever the command line left unset."""
    from .config import load_config

    cfg = load_config()
    for key in ("planner", "model", "base_url", "resolver", "plan_library"):
        if hasattr(args, key) and getattr(args, key) is None and getattr(cfg, key) is not None:
            setattr(args, key, getattr(cfg, key))
    defaults = {"planner": "rules" if args.command == "plan" else "reference", "resolver": "sim",
                "plan_library": "store"}
    for key, value in defaults.items():
        if hasattr(args, key) and getattr(args, key) is None:
            setattr(args, key, value)
    if cfg.prices:
        from .planning import pricing

        pricing.PRICES_USD_PER_MTOK.update(cfg.prices)


def main(argv: list[str] | None = None) -> int:
    import os

    os.environ.setdefault("MUJOCO_GL", "egl")  # headless rendering (cameras) unless the user chose a backend
    parser = build_parser()
    args = parser.parse_args(argv)
    try:
        _apply_config(args)
    except (OSError, ValueError) as e:
        print(f"configuration error: {e}", file=sys.stderr)
        return 2
    if not getattr(args, "func", None):
        parser.print_help()
        return 2
    return int(args.func(args))


if __name__ == "__main__":
    sys.exit(main())
