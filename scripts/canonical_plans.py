"""Rewrite plan files into the canonical (paper's) form, keeping their leading comment lines.

    .venv/bin/python scripts/canonical_plans.py examples/plans/*.yaml spark_core/sim/tasks/reference/*.yaml
    .venv/bin/python scripts/canonical_plans.py --check <files>   # exit 1 naming the files that are not canonical

Each rewrite is checked to parse to the same Plan as the original before the file is written."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from spark_core.grammar import parse_plan, to_yaml


def canonical(text: str) -> str:
    header = []
    for line in text.splitlines():
        if not line.startswith("#"):
            break
        header.append(line + "\n")
    plan = parse_plan(text)
    out = "".join(header) + to_yaml(plan, compact=True)
    if parse_plan(out) != plan:
        raise ValueError("the canonical form does not parse to the same plan")
    return out


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--check", action="store_true", help="only report files that are not in the canonical form")
    ap.add_argument("files", nargs="+", type=Path)
    args = ap.parse_args(argv)
    stale = []
    for path in args.files:
        text = path.read_text(encoding="utf-8")
        out = canonical(text)
        if out != text:
            stale.append(path)
            if not args.check:
                path.write_text(out, encoding="utf-8")
    for path in stale:
        print(f"{'not canonical' if args.check else 'rewrote'}: {path}")
    return 1 if args.check and stale else 0


if __name__ == "__main__":
    sys.exit(main())
