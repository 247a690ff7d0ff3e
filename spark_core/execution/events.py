"""Node life-cycle events and the thread-safe bus that fans them out (callbacks and async iterators)."""

from __future__ import annotations

import asyncio
import enum
import itertools
import threading
import time
from collections.abc import AsyncIterator, Callable
from dataclasses import asdict, dataclass, field
from typing import Any


class EventKind(enum.StrEnum):
    """What happened to a node. Shared with the API schema (`GET /api/catalog`) and the UI."""

    STARTED = "started"
    SUCCEEDED = "succeeded"
    FAILED = "failed"
    RETRYING = "retrying"
    PAUSED = "paused"


EVENT_KINDS = tuple(k.value for k in EventKind)


@dataclass(frozen=True)
class Event:
    """`t` is monotonic seconds since the bus was created (trial start); `seq` orders events totally;
    `wall_s` is the Unix time of publication (for latency measurements across processes); `t_sim` is the
    world's simulated seconds at publication (the clock of recorded scene states and groundings; None when
    the bus has no sim clock)."""

    trial_id: str
    seq: int
    t: float
    node_path: str
    kind: str
    detail: dict[str, Any] = field(default_factory=dict)
    wall_s: float = 0.0
    t_sim: float | None = None

    def to_dict(self) -> dict[str, Any]:
        return asdict(self)


class EventBus:
    """Publish from any thread; subscribe with a callback or `async for ev in bus.stream()`.

    `sim_clock` returns the simulated seconds of the world the trial runs in; whoever owns the world sets it
    (run_trial does), so every event is stamped with the simulated time at which it happened."""

    def __init__(self, trial_id: str = "", sim_clock: Callable[[], float] | None = None):
        self.trial_id = trial_id
        self.sim_clock = sim_clock
        self._t0 = time.monotonic()
        self._seq = itertools.count()
        self._lock = threading.RLock()
        self._callbacks: list[Callable[[Event], None]] = []
        self._queues: list[tuple[asyncio.AbstractEventLoop, asyncio.Queue]] = []
        self._closed = False
        self.history: list[Event] = []

    def now(self) -> float:
        return time.monotonic() - self._t0

    def subscribe(self, callback: Callable[[Event], None]) -> Callable[[], None]:
        with self._lock:
            self._callbacks.append(callback)

        def unsubscribe() -> None:
            with self._lock:
                if callback in self._callbacks:
                    self._callbacks.remove(callback)

        return unsubscribe

    def publish(self, node_path: str, kind: EventKind | str, **detail: Any) -> Event:
        if kind not in EVENT_KINDS:
            raise ValueError(f"unknown event kind {kind!r}; expected one of {', '.join(EVENT_KINDS)}")
        with self._lock:
            t_sim = None if self.sim_clock is None else round(float(self.sim_clock()), 6)
            ev = Event(
                self.trial_id, next(self._seq), self.now(), node_path, EventKind(kind).value, detail, time.time(), t_sim
            )
            self.history.append(ev)
            callbacks = list(self._callbacks)
            for loop, q in self._queues:
                loop.call_soon_threadsafe(q.put_nowait, ev)
        for cb in callbacks:
            cb(ev)
        return ev

    def close(self) -> None:
        """End every async stream (after the events already published)."""
        with self._lock:
            self._closed = True
            for loop, q in self._queues:
                loop.call_soon_threadsafe(q.put_nowait, None)

    async def stream(self, replay: bool = True) -> AsyncIterator[Event]:
        """Events as they are published; with `replay`, the history first. Ends when the bus closes."""
        loop = asyncio.get_running_loop()
        q: asyncio.Queue = asyncio.Queue()
        with self._lock:
            backlog = list(self.history) if replay else []
            closed = self._closed
            if not closed:
                self._queues.append((loop, q))
        try:
            for ev in backlog:
                yield ev
            if closed:
                return
            while (ev := await q.get()) is not None:
                yield ev
        finally:
            with self._lock:
                if (loop, q) in self._queues:
                    self._queues.remove((loop, q))
