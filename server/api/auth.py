"""Who may open a websocket: beyond loopback (or whenever a token is set) the client must present
SPARK_API_TOKEN as `?token=` or `Authorization: Bearer` (browsers cannot set headers on websockets)."""

from __future__ import annotations

from fastapi import WebSocket


async def websocket_allowed(websocket: WebSocket) -> bool:
    """True if the socket may proceed; otherwise it is closed with 1008 (policy violation) and False."""
    settings = websocket.app.state.settings
    if not settings.api_token and settings.loopback:
        return True
    token = websocket.query_params.get("token") or websocket.headers.get("authorization", "").removeprefix("Bearer ")
    if settings.api_token and token == settings.api_token:
        return True
    await websocket.close(code=1008, reason="authentication required: pass ?token=<SPARK_API_TOKEN>")
    return False
