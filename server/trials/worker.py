"""Trial worker processes. Each trial runs in a separate process (spawned, one trial at a time), so a crash, a
hang or a leak in one trial never takes the console down.

Wire protocol (tuples over two one-way pipes):
  console -> worker: ("run", trial_id, TrialConfig, control_state) | ("control", trial_id, action, arg) | ("stop",)
  worker -> console: ("ready", pid) | ("status", trial_id, status) | ("event", trial_id, event_dict)
                     | ("scene" | "poses" | "markers" | "image", trial_id, payload) | ("done", trial_id)
The worker runs the one trial pipeline (spark_core.run_trial) and writes the trial record itself (same store
URL, events as they happen); the console only records what a dead worker could not.
"""

from __future__ import annotations

import multiprocessing as mp
import os
import signal
import threading
import time
import traceback
from collections.abc import Callable
from pathlib import Path
from typing import Any

from spark_core import BaseSink, StepControl, TraceStore, TrialConfig, run_trial

EOF_MSG = ("eof",)  # the worker's end of the pipe closed: it exited or was killed


class WorkerProcess:
    """The console's handle on one worker process."""

    def __init__(
        self,
        store_url: str,
        artifacts_dir: str,
        feed_hz: float = 30.0,
        ready_timeout_s: float = 300.0,
        cancelled: Callable[[], bool] = lambda: False,
    ):
        ctx = mp.get_context("spawn")  # never fork a threaded server
        child_inbox, self._to_child = ctx.Pipe(duplex=False)
        self._from_child, child_outbox = ctx.Pipe(duplex=False)
        self.process = ctx.Process(
            target=child_main,
            name="spark-trial-worker",
            daemon=True,
            args=(child_inbox, child_outbox, store_url, artifacts_dir, feed_hz),
        )
        self.process.start()
        child_inbox.close()  # only the child holds these ends: its death closes the pipe (EOF here)
        child_outbox.close()
        self._send_lock = threading.Lock()
        deadline = time.monotonic() + ready_timeout_s
        while (msg := self.recv(0.5)) is None and time.monotonic() < deadline:
            if cancelled():  # the console is stopping: do not keep it waiting for a warm-up
                self.kill()
                raise RuntimeError("the console is shutting down")
        if msg is None or msg[0] != "ready":
            self.kill()
            raise RuntimeError(f"trial worker did not start within {ready_timeout_s:.0f} s ({self.death()})")
        self.pid: int = msg[1]

    @property
    def alive(self) -> bool:
        return self.process.is_alive()

    def send(self, *msg: Any) -> bool:
        with self._send_lock:
            try:
                self._to_child.send(msg)
                return True
            except (BrokenPipeError, OSError):
                return False

    def recv(self, timeout_s: float) -> tuple | None:
        """The next message, None after `timeout_s` of silence, EOF_MSG once the worker is gone."""
        try:
            if not self._from_child.poll(timeout_s):
                return None
            return self._from_child.recv()
        except (EOFError, OSError):
            return EOF_MSG

    def death(self) -> str:
        """How the process ended, for the trial's failure reason."""
        self.process.join(2.0)
        code = self.process.exitcode
        if code is None:
            return "still running"
        if code < 0:
            try:
                return f"killed by {signal.Signals(-code).name}"
            except ValueError:
                return f"killed by signal {-code}"
        return f"exit code {code}"

    def kill(self) -> None:
        if self.process.is_alive():
            self.process.kill()
        self.process.join(5.0)

    def stop(self) -> None:
        self.send("stop")
        self.process.join(5.0)
        self.kill()


# ---------------------------------------------------------------------------------------------------------------
# Worker side


def child_main(inbox, outbox, store_url: str, artifacts_dir: str, feed_hz: float) -> None:
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # Ctrl-C belongs to the console, which stops us in order
    os.environ.setdefault("MUJOCO_GL", "egl")  # before mujoco is imported: cameras render headless
    lock = threading.Lock()

    def send(*msg: Any) -> None:
        with lock:
            try:
                outbox.send(msg)
            except (BrokenPipeError, OSError):
                os._exit(0)  # the console is gone: nobody is left to report to

    parent = os.getppid()

    def orphan_watch() -> None:  # belt and braces: a pipe end leaked into another process would hide the EOF
        while os.getppid() == parent:
            time.sleep(1.0)
        os._exit(0)

    threading.Thread(target=orphan_watch, name="orphan-watch", daemon=True).start()
    store = TraceStore(store_url, migrate=False)  # the console migrated it before starting workers
    _warm_up()
    current: dict[str, Any] = {"id": None, "control": None}
    send("ready", os.getpid())
    while True:
        try:
            msg = inbox.recv()
        except (EOFError, OSError):
            os._exit(0)  # the console died: its restart marks our trial interrupted, so stop writing now
        if msg[0] == "run":
            _, trial_id, config, state = msg
            control = StepControl(state["breakpoints"])
            if state["paused"]:
                control.pause()
            for _ in range(state.get("steps", 0)):
                control.step()
            if state["aborted"]:
                control.abort()
            current.update(id=trial_id, control=control)
            threading.Thread(
                target=_job,
                args=(trial_id, config, control, store, send, Path(artifacts_dir), feed_hz),
                name=f"trial-{trial_id}",
                daemon=True,
            ).start()
        elif msg[0] == "control" and msg[1] == current["id"]:
            _, _, action, arg = msg
            c = current["control"]
            c.set_breakpoints(arg) if action == "breakpoints" else getattr(c, action)()
        elif msg[0] == "stop":
            return


def _warm_up() -> None:
    """Import the simulator and planners and load the text encoder now, so the first trial does not pay for it
    (and its 3D feed is not starved while it does)."""
    from spark_core import warm_up

    warm_up()


class _PipeSink(BaseSink):
    """Streams a trial to the console: its status, every event, and the live 3D feed (SceneFeed)."""

    def __init__(self, trial_id: str, send: Callable, feed_hz: float):
        self.trial_id, self.send, self.feed_hz = trial_id, send, feed_hz
        self.feed: Any = None

    def on_start(self, ctx) -> None:
        from ..view3d.scene_feed import SceneFeed

        self.send("status", self.trial_id, "running")
        self.feed = SceneFeed(
            ctx.world, lambda kind, payload: self.send(kind, self.trial_id, payload), self.feed_hz, ctx.resolver
        ).start()

    def on_event(self, event) -> None:
        self.send("event", self.trial_id, event.to_dict())

    def on_finish(self, ctx, outcome) -> None:
        if self.feed is not None:
            self.feed.stop()


def _job(
    trial_id: str,
    config: TrialConfig,
    control: StepControl,
    store: TraceStore,
    send: Callable,
    artifacts_dir: Path,
    feed_hz: float,
) -> None:
    from spark_core import StorePlanLibrary, StoreSink, Verdict

    try:
        store_sink = StoreSink(store, artifacts_dir, {"worker_pid": os.getpid()}, grounding_images=True)
        sinks = [store_sink, _PipeSink(trial_id, send, feed_hz)]
        run_trial(config, sinks, control, trial_id=trial_id, library=StorePlanLibrary(store))
    except Exception as e:
        store.update_trial(
            trial_id,
            status="done",
            outcome="failure",
            success=False,
            verdict=Verdict.CRASHED.value,
            failure="internal",
            reason=f"internal error: {type(e).__name__}: {e}",
            protocol={"worker_pid": os.getpid(), "traceback": traceback.format_exc()[-4000:]},
        )
    finally:
        send("done", trial_id)
