"""Step-through control of a running plan, safe to drive from another thread (UI, REST, tests)."""

from __future__ import annotations

import threading
from collections.abc import Callable, Iterable


class Aborted(Exception):
    """Raised inside the executor when the operator aborts the trial."""


class StepControl:
    """Pause / resume / step / breakpoints / abort, checked before every primitive starts.

    - `pause()` takes effect before the next primitive.
    - `step()` lets exactly one more primitive run, then pauses again.
    - A breakpoint on a node path pauses before that primitive (before its first attempt).
    - `abort()` stops at the next checkpoint and wakes a paused executor.
    """

    def __init__(self, breakpoints: Iterable[str] = ()):
        self._cond = threading.Condition(threading.RLock())
        self._paused = False
        self._step_budget = 0
        self._aborted = False
        self._breakpoints: set[str] = set(breakpoints)
        self.paused_at: str | None = None

    # -- operator side -----------------------------------------------------------------------------------------
    def pause(self) -> None:
        with self._cond:
            self._paused = True
            self._cond.notify_all()

    def resume(self) -> None:
        with self._cond:
            self._paused = False
            self._step_budget = 0
            self._cond.notify_all()

    def step(self) -> None:
        with self._cond:
            self._paused = True
            self._step_budget += 1
            self._cond.notify_all()

    def abort(self) -> None:
        with self._cond:
            self._aborted = True
            self._cond.notify_all()

    def set_breakpoints(self, paths: Iterable[str]) -> None:
        with self._cond:
            self._breakpoints = set(paths)

    def remove_breakpoint(self, path: str) -> None:
        with self._cond:
            self._breakpoints.discard(path)

    @property
    def breakpoints(self) -> frozenset[str]:
        with self._cond:
            return frozenset(self._breakpoints)

    @property
    def aborted(self) -> bool:
        return self._aborted

    @property
    def state(self) -> str:
        with self._cond:
            if self._aborted:
                return "aborted"
            return "paused" if self.paused_at is not None else ("pausing" if self._paused else "running")

    # -- executor side -----------------------------------------------------------------------------------------
    def checkpoint(self, node_path: str, on_pause: Callable[[str, str], object] | None = None) -> None:
        """Block until `node_path` may start. Raises Aborted. `on_pause(path, why)` is called when pausing."""
        with self._cond:
            if self._aborted:
                raise Aborted(node_path)
            if self._step_budget > 0:
                self._step_budget -= 1
                return
            why = "breakpoint" if node_path in self._breakpoints else ("pause" if self._paused else "")
            if not why:
                return
            self._paused = True
            self.paused_at = node_path
            if on_pause is not None:
                on_pause(node_path, why)
            try:
                while self._paused and self._step_budget == 0 and not self._aborted:
                    self._cond.wait()
                if self._aborted:
                    raise Aborted(node_path)
                if self._step_budget > 0:
                    self._step_budget -= 1
            finally:
                self.paused_at = None

    def check_abort(self, node_path: str) -> None:
        if self._aborted:
            raise Aborted(node_path)
