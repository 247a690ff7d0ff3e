"""The FastAPI application: trace store (migrated at start), trial workers, routers, access rules."""

from __future__ import annotations

from contextlib import asynccontextmanager
from pathlib import Path

from fastapi import FastAPI
from fastapi.middleware.cors import CORSMiddleware
from starlette.routing import Match, Mount
from starlette.types import Scope

from .http_methods import HeadAndAllow
from .security.guard import Guard
from .security.redact import install_log_redaction
from .settings import Settings
from .validation import install_validation_handler


def create_app(settings: Settings | None = None) -> FastAPI:
    settings = settings or Settings.from_env()

    @asynccontextmanager
    async def lifespan(app: FastAPI):
        from spark_core import StoreLease, TraceStore

        from .trials.purge import start_purging
        from .trials.runner import TrialRunner

        store = TraceStore(settings.store_url)
        # One server per store: a second console refuses to start (LeaseHeld names the holder) before it touches
        # a trial; the first one's live trials are its own.
        lease = StoreLease(store)
        lease.acquire()
        lease.start_heartbeat()
        store.interrupt_unfinished(lease=lease, keep_queued=True)  # running ones were cut off; queued ones run now
        scene = None
        if settings.viser:
            from .view3d.viser_scene import ViserScene

            # loopback only: browsers come through /viser
            scene = ViserScene("127.0.0.1", settings.viser_port, env_map=settings.viser_env_map)
        app.state.store, app.state.settings, app.state.scene, app.state.lease = store, settings, scene, lease
        from .view3d.replay import ReplayCursors

        app.state.replays = ReplayCursors(store, scene)  # the 3D view and camera images at a page's cursor
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
            app.state.replays.close()
            if scene is not None:
                scene.stop()

    app = FastAPI(
        title="SPARK console",
        version="0.1.0",
        lifespan=lifespan,
        docs_url=None,  # /docs below: Swagger UI from our own origin (works offline), not from a CDN
        description="Typed behavior trees over anchored keypoints: trials, plans, grammar, live events.\n\n"
        "Times: every time the API serves (`created_at` of trials, batches and exports, `restore_until`, in JSON and "
        "in CSV) is ISO 8601 in UTC with an explicit offset, e.g. `2026-11-28T11:51:12.352682+00:00`; lists sorted "
        "by `created_at` are in that order. A time with no offset is read as UTC wherever one is given to the "
        "server or its store (e.g. `spark export --since`).",
    )
    # Every request and websocket passes the Guard (security/guard.py) before any route reads it; CORS, when
    # configured, wraps it so that refusals carry the CORS headers a listed origin needs to read them.
    app.add_middleware(Guard, settings=settings)
    # HEAD wherever GET works (the GET's status and headers, no body), and 405s naming all of their path's methods;
    # around the Guard, so a refusal of a HEAD request carries no body either
    app.add_middleware(HeadAndAllow, routes=app.router.routes)
    app.state.exports_writing = set()  # ids of the exports being written now (api/exports.py)
    install_log_redaction()
    install_validation_handler(app)  # 422s that never echo the input (NaN, 1e400, lone surrogates: no 500)
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
    _mount_web(app, Path(__file__).resolve().parents[1] / "web" / "dist")
    return app


def _mount_web(app: FastAPI, dist: Path) -> None:
    """The built front end (web/dist, from `make install`: npm ci && npm run build) and Swagger UI's assets,
    which the build copies from the swagger-ui-dist package into dist/swagger."""
    from fastapi.openapi.docs import get_swagger_ui_html
    from fastapi.responses import HTMLResponse
    from fastapi.staticfiles import StaticFiles

    @app.get("/docs", include_in_schema=False)
    def docs() -> HTMLResponse:
        if not (dist / "swagger" / "swagger-ui-bundle.js").is_file():
            return HTMLResponse(_NOT_BUILT, status_code=503)
        return get_swagger_ui_html(
            openapi_url=app.openapi_url or "/openapi.json",
            title=f"{app.title} - API",
            swagger_js_url="/swagger/swagger-ui-bundle.js",
            swagger_css_url="/swagger/swagger-ui.css",
            swagger_favicon_url="/favicon.svg",
        )

    if (dist / "index.html").is_file():
        app.router.routes.append(_WebMount("/", app=StaticFiles(directory=dist, html=True), name="web"))
    else:

        @app.get("/", include_in_schema=False)
        def not_built() -> HTMLResponse:
            return HTMLResponse(_NOT_BUILT, status_code=503)


class _WebMount(Mount):
    """The front end at "/", for every path but the API's. Mounted at "/" it matched /api/... too, and a request
    no API route took was the static files' to answer: POST /api/trial (a typo) got 405 Method Not Allowed with
    `allow: GET, HEAD`, PUT /api/trials the same, and HEAD /api/health 404. The API's own router answers those
    (404 for no such endpoint, 405 naming the methods the path takes)."""

    def matches(self, scope: Scope) -> tuple[Match, Scope]:
        path = scope.get("path", "")
        if path == "/api" or path.startswith("/api/"):
            return Match.NONE, {}
        return super().matches(scope)


_NOT_BUILT = (
    "<!doctype html><title>SPARK console</title><p>The console's front end is not built: run <code>make install</code>"
    " (npm ci &amp;&amp; npm run build in web/). The API is up at <code>/api</code>.</p>"
)
