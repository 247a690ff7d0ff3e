"""The `spark` command: one module per command group (grammar, catalog, run, serve, trials, bench), each
registering its subcommands here. The one package that imports both the engine and the server."""

from __future__ import annotations

import argparse
import sys

from spark_core import __version__

from . import bench, catalog, grammar, perception, run, serve, trials


def build_parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(prog="spark", description="SPARK: typed behavior trees over anchored keypoints.")
    p.add_argument("--version", action="version", version=f"spark {__version__}")
    sub = p.add_subparsers(dest="command", metavar="COMMAND")
    for module in (grammar, catalog, run, serve, trials, bench, perception):
        module.register(sub)
    return p


def _apply_config(args: argparse.Namespace) -> None:
    """Settings from spark.yaml / SPARK_CONFIG fill in whatever the command line left unset."""
    from spark_core.catalog import DEFAULT_SEGMENTER
    from spark_core.config import load_config

    cfg = load_config()
    for key in ("planner", "model", "base_url", "segmenter", "plan_library"):
        if hasattr(args, key) and getattr(args, key) is None and getattr(cfg, key) is not None:
            setattr(args, key, getattr(cfg, key))
    defaults = {
        "planner": "rules" if args.command == "plan" else "reference",
        "segmenter": DEFAULT_SEGMENTER,
        "plan_library": "store",
    }
    if args.command == "bench":  # bench's --plan-library is a FILE (default: none), not the console's store
        del defaults["plan_library"]
    for key, value in defaults.items():
        if hasattr(args, key) and getattr(args, key) is None:
            setattr(args, key, value)
    if cfg.prices:
        from spark_core.planning import pricing

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


__all__ = ["build_parser", "main"]
