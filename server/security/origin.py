"""Same-origin rule for websockets and mutating requests: a browser page may drive the console only from the
console's own origin or one listed in SPARK_CORS_ORIGINS. Clients that send no Origin (curl, SDKs) pass."""

from __future__ import annotations

from urllib.parse import urlsplit

from starlette.datastructures import Headers


def origin_allowed(headers: Headers, allowed: tuple[str, ...]) -> bool:
    origin = headers.get("origin")
    if origin is None:
        return True
    if origin.rstrip("/") in allowed:
        return True
    host = headers.get("host", "")
    netloc = urlsplit(origin).netloc
    return bool(netloc) and netloc.lower() == host.lower()


def json_content_type(headers: Headers) -> bool:
    """application/json or application/<something>+json: a type no HTML form can send without a CORS preflight."""
    mime = headers.get("content-type", "").split(";", 1)[0].strip().lower()
    return mime == "application/json" or (mime.startswith("application/") and mime.endswith("+json"))
