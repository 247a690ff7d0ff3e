"""How `spark serve` should run uvicorn: the app decides which X-Forwarded-For to trust (SPARK_TRUSTED_PROXIES),
so uvicorn must not rewrite the client from it first (its default trusts any header sent from 127.0.0.1)."""

from __future__ import annotations

from typing import Any


def uvicorn_options() -> dict[str, Any]:
    """Keyword arguments for `uvicorn.run` / `uvicorn.Config`."""
    from .redact import install_log_redaction

    install_log_redaction()
    return {"proxy_headers": False, "server_header": False}
