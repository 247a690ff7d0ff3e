"""Live websocket streams end when their client leaves or the server stops, not at the next event: uvicorn's
shutdown disconnects every socket, and a handler blocked on its event queue would otherwise hold the process
up (until `timeout_graceful_shutdown`)."""

from __future__ import annotations

import asyncio
import contextlib
from typing import Any

from fastapi import WebSocket, WebSocketDisconnect

GONE: Any = object()  # put on the stream's queue when the client has gone


def watch_disconnect(websocket: WebSocket, queue: asyncio.Queue) -> asyncio.Task[None]:
    """A task that reads the socket (clients send nothing we need) and puts GONE on `queue` once it closes.
    Cancel it when the stream ends."""

    async def watch() -> None:
        with contextlib.suppress(WebSocketDisconnect, RuntimeError):
            while (await websocket.receive())["type"] != "websocket.disconnect":
                pass
        queue.put_nowait(GONE)

    return asyncio.create_task(watch())


async def finish(websocket: WebSocket, watcher: asyncio.Task[None]) -> None:
    """Stop watching and close our end (already closed by a client that left: nothing to do)."""
    watcher.cancel()
    with contextlib.suppress(asyncio.CancelledError):
        await watcher
    with contextlib.suppress(RuntimeError, WebSocketDisconnect):
        await websocket.close()
