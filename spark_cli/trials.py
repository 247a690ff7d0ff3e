"""`spark trials` and `spark export`: what the trace store holds, and recorded trials as a LeRobot dataset."""

from __future__ import annotations

import argparse
import json
import sys
from datetime import UTC


def register(sub) -> None:
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
    ex.add_argument(
        "--include-failures",
        action="store_true",
        help="also failed trials (default: verified successes only, i.e. clean demonstrations)",
    )
    ex.set_defaults(func=_cmd_export)

    tr = sub.add_parser("trials", help="list recorded trials (or print one with --id)")
    tr.add_argument("--store", default="sqlite:///var/spark.db")
    tr.add_argument("--task")
    tr.add_argument("--limit", type=int, default=20)
    tr.add_argument("--id", help="print this trial's full record as JSON")
    tr.set_defaults(func=_cmd_trials)


def _cmd_trials(args: argparse.Namespace) -> int:
    """List recorded trials, or show one as JSON."""
    from spark_core.trace import TraceStore

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
        print(
            f"  {r['created_at'][:19]}  {r['verdict'] or r['status']:<13} {r['id']:<34} {r['task']:<16} "
            f"{r['planner']:<9} {r['instruction'][:50]!r}"
        )
    return 0


def _date(text: str):
    from datetime import datetime

    try:
        return datetime.strptime(text, "%Y-%m-%d").replace(tzinfo=UTC)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a date YYYY-MM-DD, got {text!r}") from None


def _cmd_export(args: argparse.Namespace) -> int:
    """Recorded trials (captured with frames) -> a LeRobot v3.0 dataset with SPARK's per-frame labels."""
    from spark_core.sim.tasks import BUILTIN
    from spark_core.trace import TraceStore
    from spark_core.trace.lerobot import ExportError, ExportFilter, export_lerobot

    tasks = tuple(args.task) or (tuple(BUILTIN) if args.suite == "builtin" else ())
    flt = ExportFilter(
        tasks=tasks,
        trial_ids=tuple(args.trial),
        batch=args.batch,
        success_only=not args.include_failures,
        since=args.since,
        until=args.until,
    )
    try:
        r = export_lerobot(TraceStore(args.store), args.out, flt)
    except ExportError as e:
        print(f"export failed: {e}", file=sys.stderr)
        return 1
    print(
        f"{r.episodes} episodes, {r.frames} frames -> {r.out_dir} ({r.bytes_on_disk / 1e6:.1f} MB, "
        f"{r.data_files} data file(s), {r.video_files} video file(s)) in {r.wall_time_s:.1f} s"
    )
    for s in r.skipped:
        print(f"  skipped {s['id']}: {s['reason']}")
    return 0
