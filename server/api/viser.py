"""The live 3D view from the console's own origin: viser's bundled client page at /viser/ and a websocket
relay at /viser to the viser server, which listens on loopback only (so the token check here guards it)."""

from __future__ import annotations

import asyncio
import contextlib
from pathlib import Path

from fastapi import APIRouter, HTTPException, Query, Request, WebSocket, WebSocketDisconnect
from fastapi.responses import FileResponse

from .auth import websocket_allowed

router = APIRouter(tags=["3d view"])


@router.get("/api/viser")
def viser_view(request: Request) -> dict:
    """Where the live 3D view is served, and what it shows."""
    scene = request.app.state.scene
    if scene is None:
        return {"enabled": False}
    return {
        "enabled": True,
        "path": "/viser/",
        "port": scene.port,
        "rate_hz": scene.rate_hz,
        "frames_published": scene.ticks,
        "showing": scene.current,
    }


@router.get("/viser/", include_in_schema=False)
def viser_client(request: Request) -> FileResponse:
    """viser's client (one self-contained page shipped in the viser wheel); it opens its websocket at /viser."""
    import viser

    if request.app.state.scene is None:
        raise HTTPException(404, "the 3D view is off (SPARK_VISER=0)")
    return FileResponse(Path(viser.__file__).parent / "client" / "build" / "index.html", media_type="text/html")


@router.websocket("/viser")
async def viser_relay(websocket: WebSocket) -> None:
    """Byte-for-byte relay between the browser and the viser server (same subprotocol both ways)."""
    from websockets.asyncio.client import connect
    from websockets.exceptions import ConnectionClosed

    if not await websocket_allowed(websocket):
        return
    scene = websocket.app.state.scene
    if scene is None:
        await websocket.close(code=1013, reason="the 3D view is off")
        return
    offered = list(websocket.scope.get("subprotocols", []))
    async with connect(
        f"ws://127.0.0.1:{scene.port}", subprotocols=offered or None, max_size=None, compression=None
    ) as upstream:
        await websocket.accept(subprotocol=upstream.subprotocol)

        async def to_browser() -> None:
            async for message in upstream:
                if isinstance(message, bytes):
                    await websocket.send_bytes(message)
                else:
                    await websocket.send_text(message)

        async def to_viser() -> None:
            while True:
                message = await websocket.receive()
                if message["type"] == "websocket.disconnect":
                    return
                await upstream.send(message["bytes"] if message.get("bytes") is not None else message["text"])

        tasks = [asyncio.create_task(to_browser()), asyncio.create_task(to_viser())]
        try:
            await asyncio.wait(tasks, return_when=asyncio.FIRST_COMPLETED)
        except (WebSocketDisconnect, ConnectionClosed):
            pass
        finally:
            for t in tasks:
                t.cancel()
            await asyncio.gather(*tasks, return_exceptions=True)
    with contextlib.suppress(RuntimeError, WebSocketDisconnect):  # already closed by the browser
        await websocket.close()


@router.post("/api/viser/focus")
def focus(
    request: Request,
    trial: str | None = Query(None, max_length=256),
    t_sim_s: float | None = Query(None, ge=0, le=1e6),
) -> dict:
    """Bind the 3D view to the trial a page shows: a live trial's own feed (other trials stop taking the view),
    or a finished trial's recorded scene at `t_sim_s` simulated seconds (default: its last state). No trial:
    unbind (the most recently started trial takes the view again)."""
    from ..view3d.replay import ReplayUnavailable

    scene = request.app.state.scene
    if scene is None:
        raise HTTPException(409, "the 3D view is off (SPARK_VISER=0)")
    # numbered as it arrives: an earlier request's seek still waiting to draw is superseded by this one
    ticket = request.app.state.replays.ticket()
    if trial is None:
        scene.focus(None)
        return {"showing": scene.current, "pinned": None, "live": False}
    if trial in request.app.state.runner.live:
        scene.focus(trial)  # its feed draws as soon as it has a scene (a queued trial: when it starts)
        return {"showing": scene.current, "pinned": scene.pinned, "live": True}
    try:
        r = request.app.state.replays.seek(trial, 1e9 if t_sim_s is None else t_sim_s, ticket=ticket)
    except KeyError:
        raise HTTPException(404, f"no trial {trial!r}") from None
    except ReplayUnavailable as e:
        scene.focus(None)
        raise HTTPException(409, str(e)) from None
    return {"showing": scene.current, "pinned": scene.pinned, "live": False, **r}
