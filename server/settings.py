"""Server settings from the environment (SPARK_*), with safe defaults: loopback only, SQLite under var/."""

from __future__ import annotations

import os
from dataclasses import dataclass, field


@dataclass(frozen=True)
class Settings:
    host: str = "127.0.0.1"
    port: int = 8000
    store_url: str = "sqlite:///var/spark.db"
    workers: int = 2  # worker processes: trials run concurrently, each in its own process
    hang_timeout_s: float = 120.0  # a worker silent this long (no events, no 3D frames) is killed
    spawn_workers_at_start: bool = False  # True for `spark serve`: the first trial does not wait for a process
    api_token: str | None = None  # required for mutating calls when bound beyond loopback
    cors_origins: tuple[str, ...] = field(default_factory=tuple)
    # DNS names (beyond localhost and IP addresses) a console without a token answers to (server/security/origin.py)
    allowed_hosts: tuple[str, ...] = field(default_factory=tuple)
    artifacts_dir: str = "var/artifacts"  # annotated detection images, one directory per trial
    exports_dir: str = "var/exports"  # datasets exported from the console (LeRobot), one directory + zip each
    viser: bool = True  # live 3D view of the running trial (viser on its own port)
    viser_port: int = 0  # 0 = any free port
    # image-based lighting in the 3D view: off by default, its environment map's one-time preprocessing took ~4 s
    # of the GPU process with software WebGL (no GPU), freezing the whole page (docs/profiles/console_latency.md)
    viser_env_map: bool = False
    rate_per_s: float = 20.0  # mutating calls per second per client, sustained
    rate_burst: float = 40.0
    expensive_rate_per_s: float = 8.0  # reads that build and render a scene (camera.png, preview.png), per client
    expensive_burst: float = 30.0  # a page scrubbing its time cursor asks for a few at once
    auth_failures_max: int = 10  # wrong credentials from one client within the window, then 429 until it passes
    auth_failure_window_s: float = 60.0
    # Proxies whose X-Forwarded-For names the real client (IPs or CIDRs). None by default: the header is ignored.
    trusted_proxies: tuple[str, ...] = field(default_factory=tuple)
    max_body_bytes: int = 1024 * 1024  # request bodies, streamed (chunked) ones included
    # open websockets (event streams, the 3D view's relay) at once, over all clients: a browser tab holds 2-3
    max_websockets: int = 64
    delete_grace_s: float = 24 * 3600.0  # a deleted trial can be restored this long, then it is purged with its files
    purge_every_s: float = 600.0
    shutdown_timeout_s: float = 2.5  # running trials are stopped (recorded interrupted) within this on shutdown

    @classmethod
    def from_env(cls) -> Settings:
        e = os.environ
        return cls(
            host=e.get("SPARK_HOST", cls.host),
            port=int(e.get("SPARK_PORT", cls.port)),
            store_url=e.get("SPARK_STORE_URL", cls.store_url),
            workers=int(e.get("SPARK_WORKERS", os.cpu_count() or cls.workers)),
            hang_timeout_s=float(e.get("SPARK_HANG_TIMEOUT_S", cls.hang_timeout_s)),
            api_token=e.get("SPARK_API_TOKEN") or None,
            cors_origins=tuple(o.strip() for o in e.get("SPARK_CORS_ORIGINS", "").split(",") if o.strip()),
            allowed_hosts=tuple(h.strip() for h in e.get("SPARK_ALLOWED_HOSTS", "").split(",") if h.strip()),
            trusted_proxies=tuple(p.strip() for p in e.get("SPARK_TRUSTED_PROXIES", "").split(",") if p.strip()),
            viser=e.get("SPARK_VISER", "1") != "0",
            artifacts_dir=e.get("SPARK_ARTIFACTS_DIR", cls.artifacts_dir),
            exports_dir=e.get("SPARK_EXPORTS_DIR", cls.exports_dir),
            viser_port=int(e.get("SPARK_VISER_PORT", 0)),
            viser_env_map=e.get("SPARK_VISER_ENV_MAP", "0") == "1",
            delete_grace_s=float(e.get("SPARK_DELETE_GRACE_S", cls.delete_grace_s)),
            max_websockets=int(e.get("SPARK_MAX_WEBSOCKETS", cls.max_websockets)),
        )

    @property
    def loopback(self) -> bool:
        return self.host in ("127.0.0.1", "localhost", "::1")
