"""StoreLease: one holder of a named lease on a trace store at a time (the console: one server per store).

The holder's row names it (owner id, pid, host) and carries a heartbeat. A second would-be holder gets
`LeaseHeld` naming the first, unless the lease is stale: its heartbeat is older than `stale_after_s`, or its
holder ran on this host and that process is gone (a server killed with SIGKILL restarts at once, without
waiting out the heartbeat).
"""

from __future__ import annotations

import os
import socket
import threading
import time
import uuid
from dataclasses import dataclass
from pathlib import Path

from sqlalchemy import delete, exc, select

from .models import LeaseRow
from .store import TraceStore

_OWNERS_HERE: set[str] = set()  # leases this process created: the same pid with another owner is a past life


class LeaseHeld(RuntimeError):
    """Someone else holds the lease; the message names them and when they were last seen."""


@dataclass(frozen=True)
class LeaseHolder:
    owner: str
    pid: int
    host: str
    heartbeat_at: float  # epoch seconds

    def describe(self) -> str:
        age = max(0.0, time.time() - self.heartbeat_at)
        return f"process {self.pid} on {self.host} (lease {self.owner}, last heartbeat {age:.0f} s ago)"


class StoreLease:
    """Acquire with `acquire()` (returns the previous holder it took over from, or None), keep alive with
    `start_heartbeat()`, give back with `release()`."""

    def __init__(self, store: TraceStore, name: str = "console", stale_after_s: float = 15.0, heartbeat_s: float = 3.0):
        self.store, self.name = store, name
        self.stale_after_s, self.heartbeat_s = stale_after_s, heartbeat_s
        self.owner = uuid.uuid4().hex[:16]
        _OWNERS_HERE.add(self.owner)
        self.pid, self.host = os.getpid(), socket.gethostname()
        self._stop = threading.Event()
        self._thread: threading.Thread | None = None

    def holder(self) -> LeaseHolder | None:
        with self.store.Session() as s:
            row = s.get(LeaseRow, self.name)
            return None if row is None else LeaseHolder(row.owner, row.pid, row.host, row.heartbeat_at)

    def stale(self, holder: LeaseHolder) -> bool:
        if time.time() - holder.heartbeat_at > self.stale_after_s:
            return True
        if holder.host != self.host:
            return False
        if holder.pid == self.pid:  # a restarted container keeps its pid (1): was it this process?
            return holder.owner not in _OWNERS_HERE
        return not _process_alive(holder.pid)

    def refuse_if_held(self) -> None:
        """Raise LeaseHeld unless the lease is ours, free or stale."""
        self._refuse(self.holder())

    def _refuse(self, holder: LeaseHolder | None) -> None:
        if holder is not None and holder.owner != self.owner and not self.stale(holder):
            raise LeaseHeld(
                f"the store {self.store.url} is in use by another SPARK console: {holder.describe()}. "
                "Stop that server, or give this one its own store (--store)."
            )

    def acquire(self) -> LeaseHolder | None:
        """Take the lease if it is free or stale; raise LeaseHeld naming a live holder. Two servers starting
        together cannot both win: the loser's write conflicts (primary key, or SQLite's snapshot check) and it
        looks again, now seeing the winner."""
        for attempt in range(5):
            try:
                return self._take()
            except (exc.IntegrityError, exc.OperationalError):
                if attempt == 4:
                    raise
                time.sleep(0.05 * (attempt + 1))
        raise AssertionError("unreachable")

    def _take(self) -> LeaseHolder | None:
        now = time.time()
        with self.store.Session.begin() as s:
            row = s.scalars(select(LeaseRow).where(LeaseRow.name == self.name).with_for_update()).first()
            previous = None if row is None else LeaseHolder(row.owner, row.pid, row.host, row.heartbeat_at)
            self._refuse(previous)
            if row is not None:
                s.delete(row)
                s.flush()
            s.add(
                LeaseRow(
                    name=self.name, owner=self.owner, pid=self.pid, host=self.host, acquired_at=now, heartbeat_at=now
                )
            )
        return previous

    def renew(self) -> bool:
        """Refresh the heartbeat; False if the lease is no longer ours (taken over after we went stale)."""
        with self.store.Session.begin() as s:
            row = s.get(LeaseRow, self.name)
            if row is None or row.owner != self.owner:
                return False
            row.heartbeat_at = time.time()
            return True

    def start_heartbeat(self) -> None:
        def beat() -> None:
            while not self._stop.wait(self.heartbeat_s):
                try:
                    self.renew()
                except Exception:  # a busy or briefly locked database: try again next beat
                    continue

        self._thread = threading.Thread(target=beat, name=f"lease-{self.name}", daemon=True)
        self._thread.start()

    def release(self) -> None:
        self._stop.set()
        if self._thread is not None:
            self._thread.join(2.0)
        with self.store.Session.begin() as s:
            s.execute(delete(LeaseRow).where(LeaseRow.name == self.name, LeaseRow.owner == self.owner))


def _process_alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:  # someone else's process: it exists
        return True
    try:  # killed but not yet reaped by its parent: gone all the same
        return Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[0] != "Z"
    except (OSError, IndexError):
        return True
