"""`spark bench SUITE`: benchmarks, optionally written into their section of BENCHMARKS.md."""

from __future__ import annotations

import argparse
import json
import sys
from dataclasses import replace
from pathlib import Path

from spark_core.bench.run_file import write_rows
from spark_core.catalog import DEFAULT_SEGMENTER, EMBODIMENTS, PLANNERS, SEGMENTERS

from . import bench_manifest


def register(sub) -> None:
    b = sub.add_parser("bench", help="run a benchmark and optionally write its section of BENCHMARKS.md")
    b.add_argument(
        "suite",
        nargs="?",  # none with --from-manifest: the manifest names it
        choices=[
            "builtin",
            "bimanual",
            "capbench",
            "liberopro",
            "liberopro-table",
            "liberopro-ablation",
            "embodiments",
            "grounding",
            "paraphrases",
            "wording",
            "ik",
            "speed",
            "api",
            "latency",
            "viser",
            "console",
            "export",
            "throughput",
            "perception",
        ],
    )
    b.add_argument("--embodiment", choices=list(EMBODIMENTS), help="robot set-up (default: the task's own)")
    b.add_argument(
        "--embodiments",
        nargs="+",
        default=list(EMBODIMENTS),
        choices=list(EMBODIMENTS),
        help="robot set-ups compared by the embodiments suite",
    )
    b.add_argument(
        "--trials",
        type=int,
        help="trials (seeds) per task (default 20, or the whole --split; wording suite: seeds per sampled entry, "
        "default 10)",
    )
    b.add_argument("--tasks", nargs="*", help="subset of task names")
    b.add_argument("--seed", type=int, default=0, help="first seed")
    b.add_argument(
        "--planner",
        default="reference",
        choices=list(PLANNERS),
        help="reference (hand-written plans), or one planner call per trial (liberopro has no reference plans)",
    )
    b.add_argument("--model", help="LLM model name for an LLM planner")
    b.add_argument("--base-url", help="an ad-hoc LLM URL for an LLM planner (a local server; it gets no key)")
    b.add_argument("--endpoint", help="a named LLM endpoint from spark.yaml `endpoints:` (with its key)")
    b.add_argument(
        "--segmenter",
        default=DEFAULT_SEGMENTER,
        choices=list(SEGMENTERS),
        action=_Given,
        help=f"perception backend (default: {DEFAULT_SEGMENTER}, camera-only; the wording suite: sim, as its "
        "recorded table): privileged-keypoints (simulator state, no cameras: control alone), the sim / sim-noisy "
        "oracles through the cameras, or sam3 (`spark catalog` says which are privileged)",
    )
    b.add_argument("--sam3-model", help="SAM3 checkpoint directory for --segmenter sam3 (default: SPARK_SAM3_MODEL)")
    b.add_argument("--no-adaptive", action="store_true", help="one prompt per label (no adaptive self-consistency)")
    b.add_argument("--no-recovery", action="store_true", help="no retries (recovery tiers off)")
    b.add_argument("--miss-rate", type=float, default=0.2, help="sim-noisy detector miss rate")
    b.add_argument(
        "--cameras",
        nargs="+",
        help="cameras perception fuses (default: agentview side; robosuite suites: agentview sideview)",
    )
    b.add_argument(
        "--protocol",
        choices=list(_protocol_names()),
        help="a named evaluation configuration of the paper (sets adaptive prompts and cameras; refuses a "
        "privileged segmenter): " + "; ".join(f"{n}: {d}" for n, d in _protocol_names().items()),
    )
    b.add_argument(
        "--llm-loopback",
        action="store_true",
        help="run --planner gemini against a loopback stand-in on 127.0.0.1 (spark_core.bench.loopback_llm: the "
        "real google-genai client; answers from the rules parser and planner): smoke runs without a key",
    )
    b.add_argument("--title", help="BENCHMARKS.md section title (default derived from the segmenter)")
    b.add_argument("--workers", type=int, default=1, help="worker processes (local pool) or CPUs (a local Ray cluster)")
    b.add_argument(
        "--executor",
        choices=["local", "ray"],
        default="local",
        help="local process pool, or Ray (a local cluster, or --ray-address for an existing one)",
    )
    b.add_argument(
        "--ray-address",
        help="existing Ray cluster's GCS address, e.g. 127.0.0.1:6379 (`ray start --head` here, more nodes with "
        "`ray start --address`) or auto; ray:// client addresses need the ray[client] extra, not installed",
    )
    b.add_argument("--store", help="also record every trial in this trace store (SQLAlchemy URL) as one batch")
    b.add_argument(
        "--plan-library",
        metavar="FILE.jsonl",
        help="LLM planners get few-shot examples from this plan library (JSON lines), read-only for the run; "
        "its hash goes into the run manifest (default: no library)",
    )
    b.add_argument(
        "--suites",
        nargs="+",
        default=["builtin"],
        choices=["builtin", "capbench", "liberopro"],
        help="suites the throughput bench measures",
    )
    b.add_argument(
        "--scene-sources",
        nargs="+",
        default=["builtin", "random", "libero"],
        choices=["builtin", "random", "libero", "capbench"],
        help="perception suite: the held-out scene sources it measures (capbench: the seven CaP-Bench tasks' scenes)",
    )
    b.add_argument(
        "--perception-weights",
        metavar="FILE.pt",
        help="perception suite: measure these per-pixel network weights instead of the shipped ones",
    )
    b.add_argument(
        "--scenes-per-task",
        type=int,
        default=3,
        help="held-out scenes per builtin task (perception suite; random scenes: 7x as many)",
    )
    b.add_argument("--targets", type=int, default=200, help="IK targets (ik suite)")
    b.add_argument(
        "--runs",
        nargs="+",
        metavar="FILE.json",
        help="liberopro-table / liberopro-ablation: runs to compare (files written by `spark bench liberopro --json`)",
    )
    b.add_argument("--store-size", type=int, default=10_000, help="trials in the trace store (api, console suites)")
    b.add_argument("--write", metavar="BENCHMARKS.md", help="replace this benchmark's section in the file")
    b.add_argument("--json", metavar="FILE", help="also write per-trial rows as JSON (gzipped when FILE ends in .gz)")
    b.add_argument(
        "--half",
        choices=["dev", "test"],
        help="wording suite: plan and execute only this half of the corpus (default: both; develop on dev alone)",
    )
    b.add_argument(
        "--corpus",
        metavar="FILE.yaml",
        help="wording suite: plan this corpus file (dev.yaml's schema, e.g. a probe) instead of the halves; "
        "its rows are reported in the dev column",
    )
    b.add_argument(
        "--plan-only",
        action="store_true",
        help="wording suite: the planning check alone, without the execution sample (trials take minutes)",
    )
    b.add_argument(
        "--blind",
        action="store_true",
        help="wording suite: print counts and aggregate figures only (no per-entry lines with ids and styles, no "
        "failure list), for a half or probe kept as an unseen sample",
    )
    bench_manifest.add_arguments(b)
    b.set_defaults(func=_cmd_bench)


class _Given(argparse.Action):
    """Stores the value and notes that it was given (`<dest>_given`), so a suite with a default of its own (the
    wording suite's sim) can tell the shared default from an explicit choice."""

    def __call__(self, parser, namespace, values, option_string=None):
        setattr(namespace, self.dest, values)
        setattr(namespace, f"{self.dest}_given", True)


def wording_segmenter(args: argparse.Namespace) -> str:
    """The wording suite's segmenter: as given with --segmenter, else the one its recorded table used (sim)."""
    from spark_core.bench import wording

    return args.segmenter if getattr(args, "segmenter_given", False) else wording.SEGMENTER


def _protocol_names() -> dict[str, str]:
    from spark_core.bench.protocols import PROTOCOLS

    return {p.name: p.description for p in PROTOCOLS.values()}


def _protocol_line(args: argparse.Namespace) -> str:
    """The named protocol, and why a smoke figure here is not the paper's."""
    from spark_core.bench.protocols import describe
    from spark_core.perception.sam3_segmenter import describe_checkpoint

    line = describe(args.protocol) + (
        "; SMOKE FIGURE: this machine has no SAM3 weights (segmenter "
        + (f"sam3 with {describe_checkpoint(args.sam3_model)}" if args.segmenter == "sam3" else args.segmenter)
        + ") and no Gemini key, so these configurations cannot reach real success here"
    )
    if args.llm_loopback:
        line += (
            "; planner: the google-genai client against the loopback stand-in (spark_core.bench.loopback_llm: "
            "objects from the rules parser, plans from the rules planner), not Gemini"
        )
    return line


def _simple_benches(args: argparse.Namespace) -> dict:
    """suite -> (BENCHMARKS.md title, run(), section(result, command)); imports stay lazy."""
    from spark_core.bench import control_bench

    from .console_bench import api, console, latency, viser

    return {
        "ik": ("IK (Panda, pinocchio)", lambda: control_bench.ik_benchmark(args.targets), control_bench.ik_section),
        "speed": ("simulation speed", control_bench.speed_benchmark, control_bench.speed_section),
        "api": ("console API latency", lambda: api.run(args.store_size), api.section),
        "latency": ("console event latency (executor to browser)", latency.run, latency.section),
        "viser": ("live 3D view frame rate", viser.run, viser.section),
        "console": (
            "console in a real browser (Run to running, event to screen, 3D frame rate, page loads)",
            lambda: console.run(store_size=args.store_size),
            console.section,
        ),
        "export": ("training-data export (LeRobot)", lambda: _export_bench(args), _export_section),
        "throughput": ("batch throughput (local pool vs Ray)", lambda: _throughput(args), _throughput_section),
    }


def _export_bench(args: argparse.Namespace) -> dict:
    from spark_core.bench import export_bench

    def progress(row: dict) -> None:
        print(
            f"{'ok  ' if row['success'] else 'FAIL'} {row['task']} seed {row['seed']} ({row['wall_time_s']:.1f} s)",
            flush=True,
        )

    return export_bench.run(args.trials, args.workers, progress)


def _throughput(args: argparse.Namespace) -> dict:
    from spark_core.bench import throughput

    return throughput.run(args.trials, args.workers, args.segmenter, tuple(args.suites))


def _throughput_section(r: dict, command: str) -> str:
    from spark_core.bench import throughput

    return throughput.section(r, command)


def _export_section(r: dict, command: str) -> str:
    from spark_core.bench import export_bench

    return export_bench.section(r, command)


def _wording(args: argparse.Namespace, command: str) -> str:
    """Both corpus halves planned, then (unless --plan-only) the execution sample (--trials seeds each, default
    wording.EXEC_SEEDS)."""
    from spark_core.bench import wording

    if getattr(args, "corpus", None):
        entries = wording.load_file(args.corpus)
    else:
        entries = [e for half in ([args.half] if args.half else wording.HALVES) for e in wording.load(half)]
    blind = bool(getattr(args, "blind", False))
    segmenter = wording_segmenter(args)
    done = iter(range(1, len(entries) + 1))
    rows = wording.plan_entries(
        entries,
        args.seed,
        lambda r: print(
            f"[{next(done)}/{len(entries)}] planned" if blind or r["half"] == "test" else _wording_line(r), flush=True
        ),
        segmenter=segmenter,
    )
    seeds = args.trials or wording.EXEC_SEEDS
    exec_rows = (
        []
        if args.plan_only
        else wording.execute_sample(
            entries,
            seeds,
            lambda r: print(
                "trial done"
                if blind or r["half"] == "test"
                else f"{'ok  ' if r['success'] else 'FAIL'} {r['half']} {r['task'][:40]} {r['wording']}",
                flush=True,
            ),
            segmenter=segmenter,
        )
    )
    if args.json:
        write_rows(args.json, wording.json_rows(rows, exec_rows, blind=blind))
    return wording.section(rows, exec_rows, command, seeds, list_failures=not blind, segmenter=segmenter)


def _wording_line(r: dict) -> str:
    """One entry's progress: id, style and outcome only. No instruction text or planner message (which quotes the
    words), so a progress log leaks no wording that someone keeps aside as an unseen sample."""
    mark = {True: "ok  ", False: "FAIL", None: "n/a "}[r["correct"]]
    outcome = "planned" if r["planned"] else "refused"
    return f"{mark} {r['half']:<4} {r['id']:<32} {r['style']:<12} {r['expect']:<20} {outcome}"


def _cmd_bench(args: argparse.Namespace) -> int:
    bad = bench_manifest.prepare(args)  # --split, --from-manifest
    if bad is not None:
        return bad
    if not args.llm_loopback:
        return _bench(args)
    if args.planner != "gemini" or args.endpoint or args.base_url:
        print(
            "--llm-loopback stands in for Gemini: --planner gemini, without --endpoint or --base-url", file=sys.stderr
        )
        return 2
    from spark_core.bench.loopback_llm import ENDPOINT, LoopbackGemini

    with LoopbackGemini():
        args.endpoint = ENDPOINT
        return _bench(args)


def _bench(args: argparse.Namespace) -> int:
    from spark_core.bench import reference_suite
    from spark_core.bench.report import write_section

    command = "spark bench " + " ".join(sys.argv[2:]) if sys.argv[1:2] == ["bench"] else "spark bench " + args.suite
    exit_code = 0  # 1: a --from-manifest re-run whose verdicts differ
    simple = _simple_benches(args)  # suites whose result is one dict: print it, then its section
    if args.suite in simple:
        title, run, section = simple[args.suite]
        r = run()
        print(json.dumps(r, indent=2))
        body = section(r, command)
    elif args.suite == "paraphrases":
        from spark_core.bench import paraphrases

        rows, errors = paraphrases.run(args.seed)
        for r in rows:
            mark, why = ("ok ", "") if r["success"] else ("FAIL", r["outcome"])
            print(f"{mark} {r['task']:<16} {r['instruction']!r} {why}")
        for e in errors:
            print(f"{'refused' if e['refused'] else 'PLANNED'} {e['instruction']!r}: {e['error']}")
        title, body = "rules planner on paraphrased instructions", paraphrases.section(rows, errors, command)
        print(body)
    elif args.suite == "perception":
        from spark_core.bench import perception_bench

        result = perception_bench.run(
            suites=tuple(args.scene_sources),
            n_seeds=args.scenes_per_task,
            progress=lambda s: print(s, flush=True),
            weights=args.perception_weights,
            round_=args.seed,
        )
        title = "perception on held-out scenes (learned segmenter)"
        if args.seed:  # a later round of scenes nobody looked at keeps a section of its own
            title = f"perception on held-out scenes, seed round {args.seed} (learned segmenter)"
        body = perception_bench.section(result, command, args.perception_weights)
        print(body)
    elif args.suite == "wording":
        segmenter = wording_segmenter(args)
        title = "rules planner on the wording corpus" + ("" if segmenter == "sim" else f" ({segmenter} segmenter)")
        body = _wording(args, command)
        print(body)
    elif args.suite == "liberopro-table":
        from spark_core.bench import liberopro_table

        if not args.runs:
            print("liberopro-table compares runs: --runs FILE.json [FILE.json ...]", file=sys.stderr)
            return 2
        try:
            runs = [(Path(f), liberopro_table.load_run(Path(f))) for f in args.runs]
        except liberopro_table.RunError as e:
            print(f"--runs: {e}", file=sys.stderr)
            return 2
        title, body = "LIBERO-PRO per cell: our runs and the published rows", liberopro_table.section(runs, command)
        print(body)
    elif args.suite == "liberopro-ablation":
        from spark_core.bench import liberopro_ablation, liberopro_table

        if not args.runs:
            print(
                "liberopro-ablation compares three runs: --runs FULL.json NO_ADAPTIVE.json NO_RECOVERY.json",
                file=sys.stderr,
            )
            return 2
        try:
            runs = [(Path(f), liberopro_table.load_run(Path(f))) for f in args.runs]
            body = liberopro_ablation.section(runs, command)
        except liberopro_table.RunError as e:
            print(f"--runs: {e}", file=sys.stderr)
            return 2
        title = "LIBERO-PRO ablations: adaptive prompts and recovery (learned segmenter)"
        print(body)
    elif args.suite == "grounding":
        from spark_core.bench import grounding

        rows = grounding.run()
        for r in rows:
            err = f"{100 * r['keypoint_error_m']:.2f} cm" if r["keypoint_error_m"] is not None else "-"
            print(f"{'ok ' if r['correct'] else 'MISS'} {r['scene']:<22} {r['prompt']!r:<36} -> {r['got']} ({err})")
        title, body = "perception grounding (sim segmenter)", grounding.section(rows, command)
        print(body)
    else:
        from spark_core.perception.noisy_segmenter import NoiseModel
        from spark_core.sim.tasks import SUITES
        from spark_core.trial import TrialConfig

        if args.suite == "liberopro" and args.planner == "reference":
            print("liberopro has no reference plans: pass --planner rules (offline) or an LLM planner", file=sys.stderr)
            return 2
        if args.suite == "embodiments" and args.planner != "reference":
            print("the embodiments suite compares reference plans: --planner reference", file=sys.stderr)
            return 2
        template = TrialConfig(
            "",
            planner=args.planner,
            model=args.model,
            base_url=args.base_url,
            endpoint=args.endpoint,
            sam3_model=args.sam3_model,
            segmenter=args.segmenter,
            cameras=tuple(args.cameras) if args.cameras else None,
            noise=NoiseModel(miss_rate=args.miss_rate),
            recovery=not args.no_recovery,
            adaptive=not args.no_adaptive,
        )
        if args.protocol:  # the paper's configuration: its prompts and cameras; never a privileged segmenter
            from spark_core.bench.protocols import PROTOCOLS, ProtocolError, apply

            if args.suite not in PROTOCOLS[args.protocol].suites:
                print(
                    f"--protocol {args.protocol} is defined on {', '.join(PROTOCOLS[args.protocol].suites)}, "
                    f"not {args.suite}",
                    file=sys.stderr,
                )
                return 2
            try:
                template = apply(args.protocol, template)
            except ProtocolError as e:
                print(f"--protocol {args.protocol}: {e}", file=sys.stderr)
                return 2
        template = bench_manifest.template_for(args, template)
        suite = SUITES[args.suite if args.suite in ("bimanual", "capbench", "liberopro") else "builtin"]
        tasks = args.tasks or list(suite)
        unknown = [t for t in tasks if t not in suite]
        if unknown:
            print(f"unknown task(s): {', '.join(unknown)}; {args.suite} tasks: {', '.join(suite)}", file=sys.stderr)
            return 2
        total = len(tasks) * args.trials
        done = [0]

        def progress(row: dict) -> None:
            done[0] += 1
            mark = "ok " if row["success"] else row["verdict"]
            print(
                f"[{done[0]:>4}/{total}] {mark} {row['task']} seed {row['seed']} "
                f"({row['sim_time_s']:.1f} s sim, {row['wall_time_s']:.2f} s wall) {row['reason'][:100]}",
                flush=True,
            )

        if args.suite == "embodiments":
            total *= len(args.embodiments)
            by_emb = {
                e: reference_suite.run(
                    tasks, args.trials, args.seed, args.workers, progress, replace(template, embodiment=e)
                )
                for e in args.embodiments
            }
            title = args.title or f"builtin reference plans on every embodiment ({args.segmenter} segmenter)"
            body = reference_suite.embodiment_section(by_emb, command, template)
            print(body)
            rows = [dict(r, embodiment=e) for e, rs in by_emb.items() for r in rs]
        else:
            template = replace(template, embodiment=args.embodiment)
            manifest = bench_manifest.start(args, tasks, template, command)
            rows = reference_suite.run(
                tasks,
                args.trials,
                args.seed,
                args.workers,
                progress,
                template,
                args.executor,
                args.ray_address,
                args.store,
                batch_id=manifest["batch_id"],
                manifest=manifest,
                plan_library=args.plan_library,
            )
            print(reference_suite.table(rows))
            suffix = "" if args.embodiment in (None, "panda") else f", {args.embodiment}"
            plans = "reference plans" if args.planner == "reference" else f"{args.planner} planner"
            title = args.title or f"{args.suite} {plans} ({args.segmenter} segmenter{suffix})"
            body = reference_suite.section(rows, command, template, args.executor)
            if args.protocol:  # every report names its protocol
                title = args.title or f"{args.suite}, protocol {args.protocol} ({plans}, {args.segmenter} segmenter)"
                body = body.replace("Protocol: ", "Protocol: " + _protocol_line(args) + "; ", 1)
            body, exit_code = bench_manifest.finish(args, manifest, rows, body)
        if args.json:
            write_rows(args.json, rows)
    if args.manifest_id is None:  # not a trial suite's run: its manifest is what it ran on
        body = bench_manifest.finish_measurement(args, body, command)
    if args.write:
        write_section(Path(args.write), title, body)
        print(f"wrote section {title!r} of {args.write}")
    return exit_code
