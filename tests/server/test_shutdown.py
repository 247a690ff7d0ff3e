"""Issue 20, finding 6 against real `spark serve` processes: SIGTERM stops the console within 5 s with a trial
running and websockets open (the trial recorded interrupted, not lost); a second console on the same store
refuses to start, naming the first, and leaves its trials alone."""

import signal
import subprocess
import time

import httpx
import pytest
from websockets.exceptions import ConnectionClosed
from websockets.sync.client import connect

from spark_core import TraceStore

from .test_faults import _alive, _free_port, _serve, _wait_up


@pytest.mark.timeout(300)
def test_sigterm_stops_the_console_within_5_s_with_a_running_trial_and_open_websockets(tmp_path):
    port, db, log = _free_port(), tmp_path / "srv.db", tmp_path / "server.log"
    url = f"http://127.0.0.1:{port}"
    proc = _serve(port, db, log)
    second: subprocess.Popen | None = None
    try:
        _wait_up(url, proc, log)
        tid = httpx.post(
            url + "/api/trials", json={"task": "lift_block", "segmenter": "privileged-keypoints", "start_paused": True}
        ).json()["id"]
        for _ in range(1200):
            t = httpx.get(f"{url}/api/trials/{tid}").json()
            if any(e["kind"] == "paused" for e in t["events"]):
                break
            time.sleep(0.1)
        assert t["status"] == "running" and t["worker_pid"]
        trial_ws = connect(f"ws://127.0.0.1:{port}/api/trials/{tid}/events", open_timeout=10)
        dashboard_ws = connect(f"ws://127.0.0.1:{port}/api/events", open_timeout=10)
        assert trial_ws.recv(timeout=10)  # the trial's history streams

        # a second console on the same store: refused, naming the first; the first one's trial untouched
        other_log = tmp_path / "second.log"
        second = _serve(_free_port(), db, other_log)
        assert second.wait(120) != 0
        assert "in use by another SPARK console" in other_log.read_text()
        assert f"process {proc.pid} on" in other_log.read_text()
        assert httpx.get(f"{url}/api/trials/{tid}").json()["status"] == "running"

        t0 = time.monotonic()
        proc.send_signal(signal.SIGTERM)
        proc.wait(10)
        stopped_in = time.monotonic() - t0
        assert stopped_in < 5.0, f"took {stopped_in:.1f} s:\n{log.read_text()[-3000:]}"
        for ws in (trial_ws, dashboard_ws):  # our streams were closed, not left hanging
            with pytest.raises(ConnectionClosed):
                while True:
                    ws.recv(timeout=5)
        time.sleep(0.5)
        assert not _alive(t["worker_pid"])
        after = TraceStore(f"sqlite:///{db}").get_trial(tid)
        assert after["status"] == "interrupted" and after["verdict"] == "interrupted", after
        assert "server shut down while the trial was running" in after["reason"]
        assert ("tree.children[0]", "paused") in [(e["node_path"], e["kind"]) for e in after["events"]]  # kept
    finally:
        for p in (proc, second):
            if p is not None and p.poll() is None:
                p.kill()
                p.wait(10)
