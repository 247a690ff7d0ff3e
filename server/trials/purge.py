"""Deleted trials are kept for a grace period (restorable), then purged with their artifact files."""

from __future__ import annotations

import logging
import threading
from collections.abc import Callable
from pathlib import Path

from spark_core import TraceStore

log = logging.getLogger("spark.purge")


def start_purging(store: TraceStore, grace_s: float, artifacts_dir: str | Path, every_s: float) -> Callable[[], None]:
    """Purge now and then every `every_s` seconds on a daemon thread; returns the function that stops it."""
    stop = threading.Event()

    def loop() -> None:
        while True:
            try:
                purged = store.purge_deleted(grace_s, artifacts_dir)
                if purged:
                    log.info("purged %d trial(s) deleted more than %.0f s ago", len(purged), grace_s)
            except Exception:  # a locked or busy store: the next round tries again
                log.exception("purging deleted trials failed")
            if stop.wait(every_s):
                return

    thread = threading.Thread(target=loop, name="purge-deleted", daemon=True)
    thread.start()

    def stopper() -> None:
        stop.set()
        thread.join(2.0)

    return stopper
