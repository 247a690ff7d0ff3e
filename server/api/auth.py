"""Websocket admission beyond the Guard. Credentials and the same-origin rule are checked for every websocket by
server.security.guard.Guard before any endpoint runs (cookie or `Authorization: Bearer`; never `?token=`); what
is left here is what only the endpoint knows: whether the thing the socket is about exists."""

from __future__ import annotations

from fastapi import WebSocket
from fastapi.responses import JSONResponse


async def websocket_allowed(websocket: WebSocket, trial_id: str | None = None) -> bool:
    """True if the socket may be accepted. For a trial's stream, a trial that is neither live nor stored is
    answered 404 before the upgrade (close 1008 where the server cannot answer in HTTP), and False."""
    if trial_id is None or trial_id in websocket.app.state.runner.live:
        return True
    if websocket.app.state.store.trial_ids(ids=(trial_id,)):
        return True
    detail = f"no trial {trial_id!r}"
    if "websocket.http.response" in websocket.scope.get("extensions", {}):
        await websocket.send_denial_response(JSONResponse({"detail": detail}, status_code=404))
    else:
        await websocket.close(code=1008, reason=detail)
    return False
