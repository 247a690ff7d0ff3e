"""World monitors that tie simulated time to the wall clock (pacing) or bound it (a trial's time limit)."""

from __future__ import annotations

import time
from collections.abc import Callable
from typing import Any


class Pacer:
    """Slows a world to `rate` x real time (1.0 = real time, 0.25 = four times slower) so an operator can
    watch it. Time spent paused or behind (a slow render) is not made up later: the clock re-anchors."""

    MAX_LAG_S = 0.25

    def __init__(self, rate: float):
        if not 0.01 <= rate <= 100.0:
            raise ValueError(f"pacing rate must be in [0.01, 100] x real time, got {rate}")
        self.rate = rate
        self._anchor: tuple[float, float] | None = None  # (wall s, sim s)

    def __call__(self, world: Any) -> None:
        now, sim = time.monotonic(), world.sim_time_s
        if self._anchor is None:
            self._anchor = (now, sim)
            return
        wall0, sim0 = self._anchor
        target = wall0 + (sim - sim0) / self.rate
        if target > now:
            time.sleep(target - now)
        elif now - target > self.MAX_LAG_S:
            self._anchor = (now, sim)


class SimTimeLimit:
    """Calls `on_expire` once when more than `limit_s` of simulated time has passed since the monitor started."""

    def __init__(self, start_s: float, limit_s: float, on_expire: Callable[[], None]):
        self.start_s, self.limit_s = start_s, limit_s
        self.expired = False
        self._on_expire = on_expire

    def __call__(self, world: Any) -> None:
        if not self.expired and world.sim_time_s - self.start_s > self.limit_s:
            self.expired = True
            self._on_expire()
