"""Per-client limits: a token bucket for mutating calls, a failure counter for wrong credentials."""

from __future__ import annotations

import time
from collections import deque

MAX_CLIENTS = 10_000  # remembered clients; the oldest are forgotten first (bounded memory under spoofed peers)


class TokenBucket:
    """`rate_per_s` calls sustained per client, `burst` at once."""

    def __init__(self, rate_per_s: float, burst: float):
        self.rate_per_s, self.burst = rate_per_s, burst
        self._buckets: dict[str, tuple[float, float]] = {}  # client -> (tokens, last refill, monotonic s)

    def allow(self, client: str) -> bool:
        now = time.monotonic()
        tokens, last = self._buckets.pop(client, (self.burst, now))
        tokens = min(self.burst, tokens + (now - last) * self.rate_per_s)
        ok = tokens >= 1.0
        self._buckets[client] = (tokens - 1.0 if ok else tokens, now)
        _forget_oldest(self._buckets)
        return ok


class FailureLimiter:
    """At most `max_failures` wrong credentials per client within `window_s`; beyond, the client is blocked
    until its oldest failure leaves the window (so guessing costs `window_s / max_failures` per try)."""

    def __init__(self, max_failures: int, window_s: float):
        self.max_failures, self.window_s = max_failures, window_s
        self._failures: dict[str, deque[float]] = {}

    def _recent(self, client: str) -> deque[float]:
        times = self._failures.get(client, deque())
        cutoff = time.monotonic() - self.window_s
        while times and times[0] < cutoff:
            times.popleft()
        return times

    def retry_after_s(self, client: str) -> float:
        """0 if the client may try its credentials now, else seconds until it may."""
        times = self._recent(client)
        if len(times) < self.max_failures:
            return 0.0
        return max(0.0, times[-self.max_failures] + self.window_s - time.monotonic())

    def fail(self, client: str) -> None:
        times = self._recent(client)
        self._failures.pop(client, None)
        times.append(time.monotonic())
        self._failures[client] = times
        _forget_oldest(self._failures)


def _forget_oldest(table: dict) -> None:
    while len(table) > MAX_CLIENTS:
        del table[next(iter(table))]
