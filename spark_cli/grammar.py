"""`spark grammar` and `spark validate`: the grammar from the registry; plan files type-checked."""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path


def register(sub) -> None:
    g = sub.add_parser("grammar", help="print the primitive grammar (generated from the registry)")
    g.add_argument("--format", choices=["table", "md", "json-schema"], default="table")
    g.set_defaults(func=_cmd_grammar)

    v = sub.add_parser("validate", help="parse and type-check plan files (YAML or JSON); exit 1 listing every error")
    v.add_argument("plans", nargs="+", metavar="PLAN", help="plan file, or - for stdin")
    v.add_argument("--canonical", action="store_true", help="print the canonical YAML of valid plans")
    v.set_defaults(func=_cmd_validate)


def _cmd_grammar(args: argparse.Namespace) -> int:
    from spark_core.grammar import plan_json_schema
    from spark_core.grammar.reference import markdown, table

    if args.format == "md":
        print(markdown())
    elif args.format == "json-schema":
        print(json.dumps(plan_json_schema(), indent=2))
    else:
        print(table())
    return 0


def _cmd_validate(args: argparse.Namespace) -> int:
    from spark_core.grammar import to_yaml, validate

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
            print(
                f"{name}: ok - {plan.task!r}: {n} primitive{'s' if n != 1 else ''}, "
                f"labels {', '.join(plan.labels()) or '-'}"
            )
            if args.canonical:
                print(to_yaml(plan))
    return status
