"""Same-origin rule for websockets and mutating requests: a browser page may drive the console only from the
console's own origin or one listed in SPARK_CORS_ORIGINS. Clients that send no Origin (curl, SDKs) pass.

The same-origin rule compares the page's Origin with the request's Host, both of which a DNS-rebinding page
chooses (its own name, re-pointed at 127.0.0.1 once loaded), so a console that asks no credentials (loopback, no
SPARK_API_TOKEN) also checks that it is addressed by a loopback name (`local_host`)."""

from __future__ import annotations

import ipaddress
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


def local_host(headers: Headers, allowed: tuple[str, ...] = ()) -> bool:
    """The request's Host names this machine as only this machine can: an IP address, `localhost` or another
    single-label name, a `*.localhost` name, or one listed in SPARK_ALLOWED_HOSTS. A dotted DNS name is what a
    DNS-rebinding page uses (a name in public DNS that answered 127.0.0.1 once the page was loaded): refused."""
    host = headers.get("host", "")
    if not host:
        return True  # HTTP/1.0 without a Host: not a browser
    try:
        name = (urlsplit("//" + host).hostname or "").rstrip(".")
    except ValueError:  # a malformed bracketed address
        return False
    try:
        ipaddress.ip_address(name)
        return True
    except ValueError:
        pass
    return "." not in name or name.endswith(".localhost") or name in {h.lower().rstrip(".") for h in allowed}
