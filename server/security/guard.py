"""The console's one gate (pure ASGI, so it sees streamed bodies and websockets before any route does):

0. a console that asks no credentials (loopback, no token) answers only requests addressed to a loopback name
   (origin.local_host: no DNS-rebinding page can reach it under its own name);
1. `GET /page?token=T` (the UI login): a session cookie and a redirect to the same page without the token;
2. websockets and mutating requests: same origin (origin.py), then credentials where they are needed (beyond
   loopback, or whenever SPARK_API_TOKEN is set), with wrong credentials limited per client (429);
   reads of /api/* (but /api/health) and /viser/: the same credentials where they are needed (a browser sends
   its session cookie; the page and its scripts stay public, they hold no data);
3. mutating requests: the per-client rate limit, JSON bodies only (415); reads that build or render a scene
   (EXPENSIVE_READS): a rate limit of their own;
4. every request: the body limit, counted as the bytes arrive (chunked bodies included; 413);
5. websockets: at most `max_websockets` open at once (SPARK_MAX_WEBSOCKETS); one more is accepted and closed
   at once with code 1013 (try again later) and a reason a browser's `onclose` can show.
"""

from __future__ import annotations

import hmac
import json
import math
import re

from starlette.datastructures import Headers
from starlette.types import ASGIApp, Message, Receive, Scope, Send

from ..settings import Settings
from . import credentials
from .clients import client_address, parse_networks
from .limits import FailureLimiter, TokenBucket
from .origin import json_content_type, local_host, origin_allowed

MUTATING = {"POST", "PUT", "PATCH", "DELETE"}
PUBLIC_READS = {"/api/health"}  # liveness probes need no token, and it says nothing
# GETs that cost seconds of CPU (a MuJoCo/robosuite scene built and rendered, or one store read per trial)
EXPENSIVE_READS = re.compile(r"^/api/(trials/[^/]+/camera\.png|tasks/[^/]+/preview\.png|batches/[^/]+/timing)$")


def _guarded_read(path: str) -> bool:
    return (path.startswith("/api/") and path not in PUBLIC_READS) or path == "/viser" or path.startswith("/viser/")


class Refusal(Exception):
    def __init__(self, status: int, detail: str, headers: list[tuple[bytes, bytes]] | None = None):
        super().__init__(detail)
        self.status, self.detail, self.headers = status, detail, headers or []


class Guard:
    def __init__(self, app: ASGIApp, settings: Settings):
        self.app, self.settings = app, settings
        self.trusted = parse_networks(settings.trusted_proxies)
        self.failures = FailureLimiter(settings.auth_failures_max, settings.auth_failure_window_s)
        self.bucket = TokenBucket(settings.rate_per_s, settings.rate_burst)
        self.expensive = TokenBucket(settings.expensive_rate_per_s, settings.expensive_burst)
        # Beyond loopback every mutating call and websocket needs credentials; on loopback only once a token is set.
        self.auth_needed = bool(settings.api_token) or not settings.loopback
        self.websockets_open = 0  # admitted and not yet returned (one event loop: no lock needed)

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] not in ("http", "websocket"):
            await self.app(scope, receive, send)
            return
        headers = Headers(scope=scope)
        try:
            if not self.auth_needed and not local_host(headers, self.settings.allowed_hosts):
                raise Refusal(
                    403,
                    f"Host {headers.get('host')!r} is not a name of this machine: a console that asks no credentials "
                    "(loopback, no SPARK_API_TOKEN) answers to localhost and IP addresses only, not to a DNS name a "
                    "web page may point here (DNS rebinding); list the name in SPARK_ALLOWED_HOSTS or set a token",
                )
            page = (
                scope["type"] == "http" and scope["method"] in ("GET", "HEAD") and not scope["path"].startswith("/api/")
            )
            if page and self.settings.api_token:  # without a token there is no login (and nothing to redirect)
                token = credentials.login_token(scope["query_string"])
                if token is not None:
                    await self._login(scope, send, token)
                    return
            if scope["type"] == "websocket" or scope["method"] in MUTATING:
                self._check_caller(scope, headers)
            elif _guarded_read(scope["path"]):
                self._check_reader(scope, headers)
            if scope["type"] == "http":
                receive = await self._bounded_body(scope, headers, receive)
        except Refusal as r:
            await _refuse(scope, send, r)
            return
        if scope["type"] == "websocket":
            await self._websocket(scope, receive, send)
            return
        await self.app(scope, receive, send)

    async def _websocket(self, scope: Scope, receive: Receive, send: Send) -> None:
        limit = self.settings.max_websockets
        if self.websockets_open >= limit:
            await _close_full(
                scope,
                receive,
                send,
                f"too many websockets: this console serves {limit} at once (SPARK_MAX_WEBSOCKETS); close a tab, retry",
            )
            return
        self.websockets_open += 1
        try:
            await self.app(scope, receive, send)
        finally:
            self.websockets_open -= 1

    def _blocked(self, client: str) -> None:
        wait_s = self.failures.retry_after_s(client)
        if wait_s > 0:
            seconds = math.ceil(wait_s)
            raise Refusal(
                429,
                f"too many failed authentication attempts from this client: retry in {seconds} s",
                [(b"retry-after", str(seconds).encode())],
            )

    def _check_caller(self, scope: Scope, headers: Headers) -> None:
        if not origin_allowed(headers, self.settings.cors_origins):
            raise Refusal(
                403,
                f"cross-origin request refused: Origin {headers.get('origin')!r} is not this console "
                "(list trusted origins in SPARK_CORS_ORIGINS)",
            )
        client = self._authenticate(scope, headers)
        if scope["type"] == "http" and not self.bucket.allow(client):
            raise Refusal(
                429,
                f"too many requests: at most {self.settings.rate_per_s:g}/s (bursts of "
                f"{self.settings.rate_burst:g}) mutating calls per client",
            )
        if scope["type"] == "http" and _has_body(headers) and not json_content_type(headers):
            raise Refusal(415, "send the request body as JSON (Content-Type: application/json)")

    def _check_reader(self, scope: Scope, headers: Headers) -> None:
        client = self._authenticate(scope, headers)
        if EXPENSIVE_READS.match(scope["path"]) and not self.expensive.allow(client):
            raise Refusal(
                429,
                f"too many scene renders: at most {self.settings.expensive_rate_per_s:g}/s (bursts of "
                f"{self.settings.expensive_burst:g}) camera, preview and timing reads per client",
                [(b"retry-after", b"1")],
            )

    def _authenticate(self, scope: Scope, headers: Headers) -> str:
        """The client's key; raises 401 where credentials are needed and missing or wrong. Only wrong ones count
        as failed attempts: a page opened without its login, or a websocket reconnecting, presents none, and
        must not lock the operator out of a shared loopback address."""
        client = client_address(scope, self.trusted)
        if self.auth_needed:
            self._blocked(client)
            if not credentials.valid(headers, self.settings.api_token):
                if credentials.presented(headers):
                    self.failures.fail(client)
                raise Refusal(
                    401,
                    "authentication required: send Authorization: Bearer <SPARK_API_TOKEN> "
                    "(browsers: open the console once as /?token=<SPARK_API_TOKEN>)",
                )
        return client

    async def _login(self, scope: Scope, send: Send, token: str) -> None:
        """Exchange the URL's token for a session cookie once; the redirect drops the token from the address bar."""
        location = credentials.clean_location(scope["path"], scope["query_string"])
        api_token = self.settings.api_token or ""
        client = client_address(scope, self.trusted)
        self._blocked(client)
        if not hmac.compare_digest(token.encode(), api_token.encode()):
            self.failures.fail(client)
            raise Refusal(401, "wrong token: open the console as /?token=<SPARK_API_TOKEN>")
        cookie = credentials.session_cookie(api_token, scope.get("scheme") == "https")
        extra = [(b"set-cookie", cookie.encode())]
        await send(
            {
                "type": "http.response.start",
                "status": 303,
                "headers": [
                    (b"location", location.encode("latin-1")),
                    (b"cache-control", b"no-store"),
                    (b"content-length", b"0"),
                    *extra,
                ],
            }
        )
        await send({"type": "http.response.body", "body": b""})

    async def _bounded_body(self, scope: Scope, headers: Headers, receive: Receive) -> Receive:
        """Reads the body (at most max_body_bytes, however it is framed) and hands it on as one message."""
        limit = self.settings.max_body_bytes
        too_big = Refusal(413, f"request body larger than {limit // 1024} KiB")
        if _declared_length(headers) > limit:
            raise too_big
        if not _has_body(headers):
            return receive
        chunks, size = [], 0
        while True:
            message = await receive()
            if message["type"] != "http.request":  # client went away: let the app see it
                return _replay([message], receive)
            chunk = message.get("body", b"")
            size += len(chunk)
            if size > limit:
                raise too_big
            chunks.append(chunk)
            if not message.get("more_body", False):
                break
        return _replay([{"type": "http.request", "body": b"".join(chunks), "more_body": False}], receive)


def _declared_length(headers: Headers) -> int:
    try:
        return int(headers.get("content-length") or 0)
    except ValueError:
        raise Refusal(400, "malformed Content-Length") from None


def _has_body(headers: Headers) -> bool:
    return "transfer-encoding" in headers or _declared_length(headers) > 0


def _replay(messages: list[Message], receive: Receive) -> Receive:
    async def replay() -> Message:
        return messages.pop(0) if messages else await receive()

    return replay


async def _close_full(scope: Scope, receive: Receive, send: Send, reason: str) -> None:
    """Accept, then close with 1013 and `reason`: a refused upgrade reaches a browser as a bare 1006 with no
    reason. The accept names the first offered subprotocol (a browser drops a handshake that names none)."""
    if (await receive())["type"] != "websocket.connect":
        return
    offered = scope.get("subprotocols") or []
    await send({"type": "websocket.accept", "subprotocol": offered[0] if offered else None})
    await send({"type": "websocket.close", "code": 1013, "reason": reason[:123]})


async def _refuse(scope: Scope, send: Send, r: Refusal) -> None:
    body = json.dumps({"detail": r.detail}).encode()
    headers = [(b"content-type", b"application/json"), (b"content-length", str(len(body)).encode()), *r.headers]
    if scope["type"] == "http":
        await send({"type": "http.response.start", "status": r.status, "headers": headers})
        await send({"type": "http.response.body", "body": body})
    elif "websocket.http.response" in scope.get("extensions", {}):  # an HTTP answer instead of the upgrade
        await send({"type": "websocket.http.response.start", "status": r.status, "headers": headers})
        await send({"type": "websocket.http.response.body", "body": body})
    else:
        await send({"type": "websocket.close", "code": 1008, "reason": r.detail[:120]})
