"""Turn-taking for the branches of `parallel` nodes on a simulated world.

Branches are threads, and each of an arm's control periods steps the one shared world. Left to the scheduler, which
branch stepped next depended on the machine's load: the same trial ran to different simulated times (two-arm
sort_bimanual, seed 0: 12.09 and 12.20 s). With `Turns`, one branch thread runs at a time and the turn passes, in
branch order, at every control period (a world monitor): arms still interleave period by period, their planning
and perception take no simulated time, and the interleaving depends only on the plan and the seed.
"""

from __future__ import annotations

import threading
from typing import Any


class Turns:
    """Who of the running branch threads may run now. `lock`: the world's lock, which a world holds while it calls
    its monitors (the waiting branch releases it, so the branch whose turn it is can step the world)."""

    def __init__(self, lock: Any = None):
        self._cond = threading.Condition(lock if lock is not None else threading.RLock())
        self._order: list[threading.Thread] = []  # the branch threads taking turns, in branch order
        self._current: threading.Thread | None = None
        self._group: dict[threading.Thread, tuple[object, threading.Thread | None]] = {}  # thread -> group, parent
        self._left: dict[object, int] = {}  # group -> its branches still running

    def spawn(self, branches: list[threading.Thread]) -> None:
        """Call before starting a parallel node's branch threads: they take the calling thread's place in the turns
        (a nested parallel) or start a rotation, and the first branch has the first turn."""
        me = threading.current_thread()
        with self._cond:
            parent = me if me in self._order else None
            group = object()
            self._left[group] = len(branches)
            for b in branches:
                self._group[b] = (group, parent)
            if parent is not None:
                i = self._order.index(parent)
                self._order[i : i + 1] = branches
            else:
                self._order.extend(branches)
            if parent is not None or self._current is None:
                self._current = branches[0]
            self._cond.notify_all()

    def begin(self) -> None:
        """A branch thread's first call: wait for its turn."""
        me = threading.current_thread()
        with self._cond:
            while self._current is not me:
                self._cond.wait()

    def end(self) -> None:
        """A branch thread's last call: leave the rotation; the last branch of a nested parallel hands the turn
        back to the branch that started it."""
        me = threading.current_thread()
        with self._cond:
            group, parent = self._group.pop(me)
            self._left[group] -= 1
            last = self._left[group] == 0
            if last:
                del self._left[group]
            i = self._order.index(me)
            if last and parent is not None:
                self._order[i] = parent
                self._current = parent
            else:
                self._order.pop(i)
                self._current = self._order[i % len(self._order)] if self._order else None
            self._cond.notify_all()

    def taking_turns(self) -> bool:
        """Whether the calling thread is a branch in the rotation."""
        with self._cond:
            return threading.current_thread() in self._order

    def pass_turn(self) -> None:
        """Give the turn to the next branch and wait until it comes back; nothing outside a rotation or alone in one."""
        me = threading.current_thread()
        with self._cond:
            if len(self._order) < 2 or me not in self._order:
                return
            i = self._order.index(me)
            self._current = self._order[(i + 1) % len(self._order)]
            self._cond.notify_all()
            while self._current is not me:
                self._cond.wait()

    def __call__(self, _world: object) -> None:
        """World monitor: called after every control period of whichever branch stepped the world."""
        self.pass_turn()
