"""`spark catalog`: the planners, segmenters (privileged or not), embodiments, suites and tasks a trial can use."""

from __future__ import annotations

import argparse
import json


def register(sub) -> None:
    c = sub.add_parser("catalog", help="list planners, segmenters, embodiments, suites and tasks")
    c.add_argument("--json", action="store_true", help="the whole catalog as JSON (what GET /api/catalog serves)")
    c.set_defaults(func=_cmd_catalog)


def _cmd_catalog(args: argparse.Namespace) -> int:
    from spark_core.catalog import ALL_EMBODIMENTS, PLANNERS, SEGMENTERS, catalog_json, suites

    if args.json:
        print(json.dumps(catalog_json(), indent=1))
        return 0
    print("planners:")
    for p in PLANNERS.values():
        print(f"  {p.name:<21} {p.description}")
    print("segmenters:")
    for s in SEGMENTERS.values():
        print(f"  {s.name:<21} {'PRIVILEGED ' if s.privileged else 'camera-only'}  {s.description}")
    print("embodiments:")
    for e in ALL_EMBODIMENTS.values():
        only = f" ({e.suite} tasks only)" if e.suite else ""
        print(f"  {e.name:<21} {e.description}{only}; arms: {', '.join(e.arms)}")
    for suite, tasks in suites().items():
        print(f"suite {suite} ({len(tasks)} tasks): {', '.join(tasks[:8])}{' ...' if len(tasks) > 8 else ''}")
    return 0
