"""How `spark serve` should run uvicorn: the app decides which X-Forwarded-For to trust (SPARK_TRUSTED_PROXIES),
so uvicorn must not rewrite the client from it first (its default trusts any header sent from 127.0.0.1); and
SIGTERM must stop the server within 5 s: uvicorn otherwise waits for every open connection and task without a
limit. Its wait is bounded here, and the app's shutdown (running trials stopped) has its own deadline."""

from __future__ import annotations

from typing import Any

GRACEFUL_SHUTDOWN_S = 1.0  # open requests and websockets (ours close as soon as uvicorn disconnects them)


def uvicorn_options() -> dict[str, Any]:
    """Keyword arguments for `uvicorn.run` / `uvicorn.Config`."""
    from .redact import install_log_redaction

    install_log_redaction()
    return {"proxy_headers": False, "server_header": False, "timeout_graceful_shutdown": GRACEFUL_SHUTDOWN_S}
