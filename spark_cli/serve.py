"""`spark serve`: the console server. The one place the engine reaches up into `server/` (lazily)."""

from __future__ import annotations

import argparse
import sys


def register(sub) -> None:
    sv = sub.add_parser("serve", help="start the console server (REST API + live events) on 127.0.0.1:8000")
    sv.add_argument("--host")
    sv.add_argument("--port", type=int)
    sv.add_argument("--store", help="trace store URL (default sqlite:///var/spark.db)")
    sv.add_argument("--workers", type=int, help="trials run concurrently (default 2)")
    sv.set_defaults(func=_cmd_serve)


def _cmd_serve(args: argparse.Namespace) -> int:
    """The console's API server (uvicorn) on the offline defaults."""
    import os
    from dataclasses import replace

    import uvicorn

    from server.app import create_app
    from server.security.serving import uvicorn_options
    from server.settings import Settings

    base = Settings.from_env()
    settings = replace(
        base,
        host=args.host or base.host,
        port=args.port or base.port,
        store_url=args.store or base.store_url,
        workers=args.workers or base.workers,
        spawn_workers_at_start=True,
    )
    if not settings.loopback and not settings.api_token:
        print(
            f"refusing to serve on {settings.host} without SPARK_API_TOKEN (trials and controls would be open)",
            file=sys.stderr,
        )
        return 2
    from spark_core import LeaseHeld, StoreLease, TraceStore

    try:  # one server per store: say so plainly here (the app's start-up takes the lease itself)
        StoreLease(TraceStore(settings.store_url)).refuse_if_held()
    except LeaseHeld as e:
        print(f"refusing to serve: {e}", file=sys.stderr)
        return 2
    os.environ.setdefault("MUJOCO_GL", "egl")
    print(f"SPARK console API on http://{settings.host}:{settings.port} (docs at /docs); store {settings.store_url}")
    uvicorn.run(create_app(settings), host=settings.host, port=settings.port, log_level="info", **uvicorn_options())
    return 0
