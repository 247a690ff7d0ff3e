"""Credentials: `Authorization: Bearer <SPARK_API_TOKEN>` (API clients) or the session cookie a browser gets by
opening the console once as `/?token=<SPARK_API_TOKEN>` (HttpOnly, SameSite=Strict; the URL is then cleaned)."""

from __future__ import annotations

import hashlib
import hmac
from urllib.parse import parse_qsl, quote, urlencode

from starlette.datastructures import Headers
from starlette.requests import cookie_parser

COOKIE = "spark_session"
LOGIN_PARAM = "token"


def session_value(token: str) -> str:
    """The cookie holds a digest of the token, not the token: a new token invalidates every session."""
    return hmac.new(token.encode(), b"spark-console-session", hashlib.sha256).hexdigest()


def presented(headers: Headers) -> bool:
    return "authorization" in headers or COOKIE in cookie_parser(headers.get("cookie", ""))


def valid(headers: Headers, token: str | None) -> bool:
    if not token:
        return False
    scheme, _, presented_token = headers.get("authorization", "").partition(" ")
    # auth schemes are case-insensitive (RFC 7235 section 2.1): "bearer" is "Bearer"
    if scheme.lower() == "bearer" and hmac.compare_digest(presented_token.strip().encode(), token.encode()):
        return True
    cookie = cookie_parser(headers.get("cookie", "")).get(COOKIE, "")
    return hmac.compare_digest(cookie.encode(), session_value(token).encode())


def login_token(query_string: bytes) -> str | None:
    """The `token` a browser brings in the URL, if any."""
    return next(
        (v for k, v in parse_qsl(query_string.decode("latin-1"), keep_blank_values=True) if k == LOGIN_PARAM), None
    )


def clean_location(path: str, query_string: bytes) -> str:
    """The same page without the token: a path on this server only. Leading slashes and backslashes go (browsers
    read `//host` and `/\\host` alike as another host), and the path is percent-quoted, so the Location can
    never name a scheme or a host: no open redirect."""
    rest = [(k, v) for k, v in parse_qsl(query_string.decode("latin-1"), keep_blank_values=True) if k != LOGIN_PARAM]
    local = quote(path.lstrip("/\\").replace("\\", "/"), safe="/-._~!$&'()*+,;=:@%")
    return "/" + local.lstrip("/") + (f"?{urlencode(rest)}" if rest else "")


def session_cookie(token: str, secure: bool) -> str:
    """Set-Cookie value: no script can read it, and no other site's page can make the browser send it."""
    return f"{COOKIE}={session_value(token)}; Path=/; HttpOnly; SameSite=Strict" + ("; Secure" if secure else "")
