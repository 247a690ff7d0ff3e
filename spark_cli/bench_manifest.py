"""`spark bench` and run manifests: `--split dev|heldout|all`, `--manifest-out FILE`, `--from-manifest FILE`.

Every trial-suite run gets a manifest (spark_core.bench.manifest): stored with its batch when `--store` is given,
its short id on the report's protocol line and in every `--json` row, printed at the end, written whole with
`--manifest-out`. `--from-manifest` re-runs exactly the recorded run and says whether the verdicts and the
environment match."""

from __future__ import annotations

import argparse
import sys
import uuid
from pathlib import Path
from typing import Any

from spark_core.bench import manifest as mf
from spark_core.bench.splits import SPLITS, describe, split_of

TRIAL_SUITES = ("builtin", "bimanual", "capbench", "liberopro")


def add_arguments(b: argparse.ArgumentParser) -> None:
    b.add_argument(
        "--split",
        choices=list(SPLITS),
        help="named seeds: dev = seeds (LIBERO-PRO init states) 0-9, heldout = 10-49, all = 0-49; "
        "replaces --seed (and --trials unless given: then the first N of the split)",
    )
    b.add_argument("--manifest-out", metavar="FILE", help="write the run's manifest (JSON) to this file")
    b.add_argument(
        "--from-manifest",
        metavar="FILE",
        help="re-run exactly the run a manifest records (suite, tasks, seeds, settings) and compare verdicts",
    )


def prepare(args: argparse.Namespace) -> int | None:
    """Resolve --from-manifest and --split into the suite, tasks, seed and trials; an exit code on bad input."""
    args.rerun, args.recorded, args.manifest_id = None, None, None
    if args.from_manifest:
        try:
            recorded = mf.load(args.from_manifest)
            rerun = mf.rerun(recorded)
        except mf.ManifestError as e:
            print(str(e), file=sys.stderr)
            return 2
        args.recorded, args.rerun = recorded, rerun
        args.suite, args.tasks, args.seed, args.trials = rerun.suite, rerun.tasks, rerun.seed, rerun.trials
        args.split, args.executor, args.workers = rerun.split, rerun.executor, rerun.workers
        args.ray_address = rerun.ray_address
        t = rerun.template
        args.planner, args.segmenter, args.embodiment = t.planner, t.segmenter, t.embodiment
        args.protocol = recorded["run"].get("protocol")
        memory = recorded["run"].get("memory", {})
        if memory.get("plan_library") == "on" and not getattr(args, "plan_library", None):
            args.plan_library = memory.get("path")
        return None
    if args.suite is None:
        print("spark bench: give a suite, or --from-manifest FILE", file=sys.stderr)
        return 2
    if getattr(args, "plan_library", None) and not Path(args.plan_library).is_file():
        print(f"--plan-library: no such file {args.plan_library}", file=sys.stderr)
        return 2
    if args.split:
        seeds = SPLITS[args.split]
        if args.seed:  # --split sets the first seed itself: a --seed beside it would be silently dropped
            print(
                f"--seed {args.seed} and --split {args.split} both choose the seeds (--split {args.split} is seeds "
                f"{seeds.start}-{seeds.stop - 1}); give one: --split with --trials N for its first N, or --seed "
                "with --trials",
                file=sys.stderr,
            )
            return 2
        args.seed = seeds.start
        args.trials = len(seeds) if args.trials is None else min(args.trials, len(seeds))
    if args.trials is None:
        args.trials = _default_trials(args.suite)
    if args.trials < 1:
        print(f"--trials: expected at least 1, got {args.trials}", file=sys.stderr)
        return 2
    return None


def _default_trials(suite: str) -> int:
    """Trials per task when --trials is not given: 20, or for the wording suite its execution sample's seeds."""
    if suite == "wording":
        from spark_core.bench.wording import EXEC_SEEDS

        return EXEC_SEEDS
    return 20


def template_for(args: argparse.Namespace, template: Any) -> Any:
    """The recorded template when re-running a manifest (every field, not only those the flags carry)."""
    return args.rerun.template if args.rerun is not None else template


def _library(args: argparse.Namespace) -> Any:
    """The run's read-only plan library (None: off)."""
    path = getattr(args, "plan_library", None)
    if not path:
        return None
    from spark_core.planning.plan_library import PlanLibrary

    return PlanLibrary(path, read_only=True)


def start(args: argparse.Namespace, tasks: list[str], template: Any, command: str) -> dict[str, Any]:
    """The run's manifest before it runs, with the batch id it will be stored under."""
    seeds = range(args.seed, args.seed + args.trials)
    return mf.build(
        suite=args.suite,
        tasks=list(tasks),
        seeds=seeds,
        template=template,
        split=args.split or split_of(seeds),
        executor=args.executor,
        workers=args.workers,
        ray_address=args.ray_address,
        command=command,
        protocol=getattr(args, "protocol", None),
        library=_library(args),
        batch_id=f"bench-{uuid.uuid4().hex[:10]}",
    )


def finish(args: argparse.Namespace, manifest: dict[str, Any], rows: list[dict], body: str) -> tuple[str, int]:
    """Complete, store, print and write the manifest; the report body with the manifest id on its protocol line,
    and the exit code (1 when a re-run's verdicts differ from the recorded ones)."""
    manifest = mf.add_trials(manifest, rows)
    args.manifest_id = manifest["id"]
    for r in rows:
        r["manifest_id"] = manifest["id"]
    if args.store:
        from spark_core.trace import TraceStore

        TraceStore(args.store, migrate=False).set_batch_manifest(manifest["batch_id"], manifest)
    if args.manifest_out:
        mf.save(manifest, args.manifest_out)
    run = manifest["run"]
    seeds = range(run["seeds"][0], run["seeds"][-1] + 1)
    line = f"; {describe(run['split'], seeds)}; run manifest `{manifest['id']}`"
    body = body.rstrip("\n") + line + "\n"
    print(mf.summary(manifest))
    if args.manifest_out:
        print(f"wrote manifest {manifest['id']} to {args.manifest_out}")
    code = 0
    if args.recorded is not None:
        changed = mf.drift(args.recorded, manifest)
        differ = mf.compare_verdicts(args.recorded, rows)
        print(f"re-run of manifest {args.recorded['id']} ({Path(args.from_manifest).name}) as {manifest['id']}")
        for d in changed:
            print(f"  environment differs: {d}")
        if differ:
            print(f"  {len(differ)} of {len(rows)} verdicts differ from the recorded run:")
            for d in differ:
                print(f"    {d}")
            code = 1
        else:
            print(f"  all {len(rows)} verdicts as recorded")
    return body, code


def finish_measurement(args: argparse.Namespace, body: str, command: str) -> str:
    """A benchmark without trial seeds (IK, speed, console latency, ...): its manifest is the code, packages and
    machine it measured; named on the protocol line like a trial suite's."""
    manifest = mf.measurement(args.suite, command)
    args.manifest_id = manifest["id"]
    if args.manifest_out:
        mf.save(manifest, args.manifest_out)
    git = manifest["environment"]["git"]
    print(f"manifest {manifest['id']}: commit {(git['commit'] or 'unknown')[:12]}{' (dirty)' if git['dirty'] else ''}")
    return body.rstrip("\n") + f"; run manifest `{manifest['id']}`\n"
