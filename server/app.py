"""The FastAPI application: trace store (migrated at start), trial workers, routers, access rules."""

from __future__ import annotations

from contextlib import asynccontextmanager
from pathlib import Path

from fastapi import FastAPI
from fastapi.middleware.cors import CORSMiddleware

from .security.guard import Guard
from .security.redact import install_log_redaction
from .settings import Settings


def create_app(settings: Settings | None = None) -> FastAPI:
    settings = settings or Settings.from_env()

    @asynccontextmanager
    async def lifespan(app: FastAPI):
        from spark_core import StoreLease, TraceStore

        from .purge import start_purging
        from .runner import TrialRunner

        store = TraceStore(settings.store_url)
        # One server per store: a second console refuses to start (LeaseHeld names the holder) before it touches
        # a trial; the first one's live trials are its own.
        lease = StoreLease(store)
        lease.acquire()
        lease.start_heartbeat()
        store.interrupt_unfinished(lease=lease, keep_queued=True)  # running ones were cut off; queued ones run now
        scene = None
        if settings.viser:
            from .viser_scene import ViserScene

            scene = ViserScene("127.0.0.1", settings.viser_port)  # loopback only: browsers come through /viser
        app.state.store, app.state.settings, app.state.scene, app.state.lease = store, settings, scene, lease
        app.state.runner = TrialRunner(
            store,
            settings.workers,
            scene,
            settings.artifacts_dir,
            settings.hang_timeout_s,
            settings.spawn_workers_at_start,
        )
        app.state.runner.requeue_recorded()
        stop_purging = start_purging(store, settings.delete_grace_s, settings.artifacts_dir, settings.purge_every_s)
        try:
            yield
        finally:
            stop_purging()
            app.state.runner.shutdown(settings.shutdown_timeout_s)
            lease.release()
            if scene is not None:
                scene.stop()

    app = FastAPI(
        title="SPARK console",
        version="0.1.0",
        lifespan=lifespan,
        description="Typed behavior trees over anchored keypoints: trials, plans, grammar, live events.",
    )
    # Every request and websocket passes the Guard (security/guard.py) before any route reads it; CORS, when
    # configured, wraps it so that refusals carry the CORS headers a listed origin needs to read them.
    app.add_middleware(Guard, settings=settings)
    install_log_redaction()
    if settings.cors_origins:
        app.add_middleware(
            CORSMiddleware, allow_origins=list(settings.cors_origins), allow_methods=["*"], allow_headers=["*"]
        )

    from .api import batches, exports, meta, trials, viser

    app.include_router(meta.router)
    app.include_router(viser.router)
    app.include_router(trials.router)
    app.include_router(batches.router)
    app.include_router(exports.router)
    app.include_router(trials.dashboard)
    web = Path(__file__).resolve().parents[1] / "web"
    if web.is_dir():
        from fastapi.staticfiles import StaticFiles

        app.mount("/", StaticFiles(directory=web, html=True), name="web")  # after the API: /api wins
    return app
