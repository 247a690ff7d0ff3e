"""The FastAPI application: trace store (migrated at start), trial workers, routers, access rules."""

from __future__ import annotations

from contextlib import asynccontextmanager
from pathlib import Path

from fastapi import FastAPI, Request
from fastapi.middleware.cors import CORSMiddleware
from fastapi.responses import JSONResponse

from .settings import Settings

MUTATING = {"POST", "PUT", "PATCH", "DELETE"}


def create_app(settings: Settings | None = None) -> FastAPI:
    settings = settings or Settings.from_env()

    @asynccontextmanager
    async def lifespan(app: FastAPI):
        from spark_core.trace import TraceStore

        from .runner import TrialRunner

        store = TraceStore(settings.store_url)
        interrupted = store.interrupt_unfinished()
        scene = None
        if settings.viser:
            from .viser_scene import ViserScene

            scene = ViserScene("127.0.0.1", settings.viser_port)  # loopback only: browsers come through /viser
        app.state.store, app.state.settings, app.state.scene = store, settings, scene
        app.state.runner = TrialRunner(store, settings.workers, scene, settings.artifacts_dir,
                                       settings.hang_timeout_s, settings.spawn_workers_at_start)
        app.state.interrupted_at_start = interrupted
        yield
        app.state.runner.shutdown()
        if scene is not None:
            scene.stop()

    app = FastAPI(title="SPARK console", version="0.1.0", lifespan=lifespan,
                  description="Typed behavior trees over anchored keypoints: trials, plans, grammar, live events.")
    if settings.cors_origins:
        app.add_middleware(CORSMiddleware, allow_origins=list(settings.cors_origins), allow_methods=["*"], allow_headers=["*"])

    buckets: dict[str, list[float]] = {}  # client -> [tokens, last refill time]

    def allowed(client: str) -> bool:
        """Token bucket per client for mutating calls: `rate_per_s` sustained, `burst` at once."""
        import time

        now = time.monotonic()
        tokens, last = buckets.get(client, [settings.rate_burst, now])
        tokens = min(settings.rate_burst, tokens + (now - last) * settings.rate_per_s)
        ok = tokens >= 1.0
        buckets[client] = [tokens - 1.0 if ok else tokens, now]
        return ok

    @app.middleware("http")
    async def guard(request: Request, call_next):
        # Beyond loopback every mutating call needs the token; on loopback the token is optional.
        if request.method in MUTATING and (settings.api_token or not settings.loopback):
            if request.headers.get("authorization") != f"Bearer {settings.api_token}" or not settings.api_token:
                return JSONResponse({"detail": "authentication required: send Authorization: Bearer <SPARK_API_TOKEN>"},
                                    status_code=401)
        if int(request.headers.get("content-length") or 0) > 1024 * 1024:
            return JSONResponse({"detail": "request body larger than 1 MiB"}, status_code=413)
        if request.method in MUTATING and not allowed(request.client.host if request.client else "?"):
            return JSONResponse({"detail": f"too many requests: at most {settings.rate_per_s:g}/s "
                                           f"(bursts of {settings.rate_burst:g}) mutating calls per client"}, status_code=429)
        return await call_next(request)

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
