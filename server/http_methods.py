"""HEAD wherever GET works, and 405s that name every method their path takes (pure ASGI).

FastAPI's routes take only the methods they are declared with: HEAD on a GET endpoint (`HEAD /api/health`, a
load balancer's probe, `curl -I`) was 405 Method Not Allowed, and HEAD /docs fell through to the front end's
files (404). HTTP wants HEAD wherever GET works (RFC 9110 9.3.2): the same status and headers, no body. A HEAD
request is answered as the GET it asks about, with the body dropped. The OpenAPI document is unchanged (HEAD is
implied by GET).

A 405 named only the methods of the first route on its path (`PUT /api/trials`: `allow: POST`, although the
path also takes GET): it now names every method the path's routes take, HEAD with GET.
"""

from __future__ import annotations

from starlette.datastructures import MutableHeaders
from starlette.routing import BaseRoute, Match, Mount
from starlette.types import ASGIApp, Message, Receive, Scope, Send


class HeadAndAllow:
    def __init__(self, app: ASGIApp, routes: list[BaseRoute]):
        self.app, self.routes = app, routes

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http":
            await self.app(scope, receive, send)
            return
        head = scope["method"] == "HEAD"
        inner = {**scope, "method": "GET"} if head else scope

        async def respond(message: Message) -> None:
            if message["type"] == "http.response.start" and message["status"] == 405:
                headers = MutableHeaders(scope=message)
                allowed = self._allowed(scope)
                if allowed:
                    headers["allow"] = ", ".join(allowed)
            if head and message["type"] == "http.response.body":
                if message.get("more_body", False):
                    return  # the GET's body, chunk by chunk: dropped; its headers (content-length too) stay
                message = {"type": "http.response.body", "body": b"", "more_body": False}
            await send(message)

        await self.app(inner, receive, respond)

    def _allowed(self, scope: Scope) -> list[str]:
        """Every method some route takes on this path (HEAD with GET), in a fixed order: each method is tried
        against the routes (mounts aside: the front end's files answer their own 405s)."""
        allowed = [
            method
            for method in _METHODS
            if any(
                not isinstance(route, Mount) and route.matches({**scope, "method": method})[0] is Match.FULL
                for route in self.routes
            )
        ]
        return allowed[:1] + ["HEAD"] + allowed[1:] if allowed[:1] == ["GET"] else allowed


_METHODS = ("GET", "POST", "PUT", "PATCH", "DELETE")
