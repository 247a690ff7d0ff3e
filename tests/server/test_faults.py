"""Isolation and durability: a worker process killed, frozen or crashing mid-trial fails only that trial, with
the reason, keeps what the trial streamed, and the console answers the next request and runs the next trial.
A real server process killed mid-trial comes back and marks the trial interrupted."""

import os
import signal
import socket
import subprocess
import sys
import time
from pathlib import Path

import httpx
import pytest
from fastapi.testclient import TestClient

from server.app import create_app
from server.settings import Settings

from .test_api import wait_done

ROOT = Path(__file__).resolve().parents[2]


def _app(tmp_path, **kw):
    return create_app(
        Settings(
            store_url=f"sqlite:///{tmp_path / 'f.db'}",
            workers=1,
            viser=False,
            artifacts_dir=str(tmp_path / "art"),
            **kw,
        )
    )


def _paused_trial(c) -> dict:
    """A trial paused before its first primitive, i.e. mid-trial inside its worker process."""
    tid = c.post(
        "/api/trials", json={"task": "lift_block", "segmenter": "privileged-keypoints", "start_paused": True}
    ).json()["id"]
    for _ in range(1200):
        t = c.get(f"/api/trials/{tid}").json()
        if any(e["kind"] == "paused" for e in t["events"]):
            return t
        time.sleep(0.1)
    raise AssertionError(f"trial {tid} never paused: {t['status']}")


def _alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    return Path(f"/proc/{pid}/status").exists() and "zombie" not in Path(f"/proc/{pid}/status").read_text()


def test_killing_the_worker_fails_the_trial_with_the_reason_and_the_console_carries_on(tmp_path):
    with TestClient(_app(tmp_path)) as c:
        trial = _paused_trial(c)
        pid = trial["worker_pid"]
        assert pid != os.getpid() and _alive(pid)
        os.kill(pid, signal.SIGKILL)
        done = wait_done(c, trial["id"])
        assert done["success"] is False and done["failure"] == "worker"
        assert f"worker process {pid} died (killed by SIGKILL)" in done["reason"]
        assert ("tree.children[0]", "paused") in [(e["node_path"], e["kind"]) for e in done["events"]]  # kept
        assert c.get("/api/health").json() == {"status": "ok"}
        nxt = c.post("/api/trials", json={"task": "lift_block", "segmenter": "privileged-keypoints"}).json()["id"]
        again = wait_done(c, nxt)
        assert again["success"] is True and again["protocol"]["worker_pid"] != pid  # a fresh process


def test_a_frozen_worker_is_killed_after_the_hang_timeout(tmp_path):
    with TestClient(_app(tmp_path, hang_timeout_s=3.0)) as c:
        trial = _paused_trial(c)  # paused, but its 3D feed keeps talking: not a hang
        time.sleep(4.0)
        assert c.get(f"/api/trials/{trial['id']}").json()["status"] == "running"
        os.kill(trial["worker_pid"], signal.SIGSTOP)  # frozen: no more messages
        done = wait_done(c, trial["id"], timeout=60)
        assert done["failure"] == "worker" and "stopped responding for 3 s and was killed" in done["reason"]
        assert not _alive(trial["worker_pid"])
        nxt = c.post("/api/trials", json={"task": "lift_block", "segmenter": "privileged-keypoints"}).json()["id"]
        assert wait_done(c, nxt)["success"] is True


def test_an_exception_inside_the_worker_is_recorded_and_the_worker_lives_on(tmp_path, monkeypatch):
    # The worker is a fresh interpreter: break one task there through sitecustomize (imported at its start).
    plugin = tmp_path / "inject"
    plugin.mkdir()
    (plugin / "sitecustomize.py").write_text(
        "import dataclasses\n"
        "from spark_core.sim.tasks import TASKS\n"
        "def crash(world, rng):\n"
        "    raise RuntimeError('simulated crash inside the trial')\n"
        "TASKS['close_drawer'] = dataclasses.replace(TASKS['close_drawer'], setup=crash)\n"
    )
    monkeypatch.setenv("PYTHONPATH", f"{plugin}{os.pathsep}{os.environ.get('PYTHONPATH', '')}")
    with TestClient(_app(tmp_path)) as c:
        tid = c.post("/api/trials", json={"task": "close_drawer", "segmenter": "privileged-keypoints"}).json()["id"]
        trial = wait_done(c, tid)
        assert trial["success"] is False and trial["failure"] == "internal"
        assert "internal error: RuntimeError: simulated crash inside the trial" in trial["reason"]
        assert "Traceback" in trial["protocol"]["traceback"]
        ok = c.post("/api/trials", json={"task": "lift_block", "segmenter": "privileged-keypoints"}).json()["id"]
        done = wait_done(c, ok)
        assert done["success"] is True and done["protocol"]["worker_pid"] == trial["protocol"]["worker_pid"]


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def _serve(port: int, db: Path, log: Path, pythonpath: Path | None = None) -> subprocess.Popen:
    env = {**os.environ, "SPARK_VISER": "0", "SPARK_WORKERS": "1", "SPARK_ARTIFACTS_DIR": str(db.parent / "art")}
    if pythonpath is not None:
        env["PYTHONPATH"] = os.pathsep.join(p for p in (str(pythonpath), env.get("PYTHONPATH", "")) if p)
    return subprocess.Popen(
        [sys.executable, "-m", "spark_cli", "serve", "--port", str(port), "--store", f"sqlite:///{db}"],
        cwd=ROOT,
        env=env,
        stdout=log.open("ab"),
        stderr=subprocess.STDOUT,
    )


def _wait_up(url: str, proc: subprocess.Popen, log: Path) -> None:
    for _ in range(600):
        if proc.poll() is not None:
            raise AssertionError(f"server exited {proc.returncode}:\n{log.read_text()[-3000:]}")
        try:
            if httpx.get(url + "/api/health", timeout=1).status_code == 200:
                return
        except httpx.HTTPError:
            pass
        time.sleep(0.1)
    raise AssertionError("server did not come up:\n" + log.read_text()[-3000:])


@pytest.mark.timeout(300)
def test_restarting_the_server_process_mid_trial_marks_the_trial_interrupted(tmp_path):
    port, db, log = _free_port(), tmp_path / "srv.db", tmp_path / "server.log"
    url = f"http://127.0.0.1:{port}"
    proc = _serve(port, db, log)
    try:
        _wait_up(url, proc, log)
        tid = httpx.post(
            url + "/api/trials", json={"task": "lift_block", "segmenter": "privileged-keypoints", "start_paused": True}
        ).json()["id"]
        for _ in range(1200):
            t = httpx.get(f"{url}/api/trials/{tid}").json()
            paused = any(e["kind"] == "paused" for e in t.get("events", []))
            if t["status"] == "running" and t.get("worker_pid") and paused:  # it has streamed events by now
                break
            time.sleep(0.1)
        worker = t["worker_pid"]
        proc.kill()  # no clean shutdown: the process is gone mid-trial
        proc.wait(10)
        for _ in range(100):  # the orphaned worker sees its pipe close and exits without writing
            if not _alive(worker):
                break
            time.sleep(0.1)
        assert not _alive(worker)
        proc = _serve(port, db, log)
        _wait_up(url, proc, log)
        after = httpx.get(f"{url}/api/trials/{tid}").json()
        assert after["status"] == "interrupted" and after["outcome"] == "aborted" and after["verdict"] == "interrupted"
        assert "server stopped" in after["reason"]
        # the events it streamed before the kill were written as they happened: none is lost
        assert [(e["node_path"], e["kind"]) for e in after["events"]] == [
            ("tree", "started"),
            ("tree.children[0]", "paused"),
        ]
        assert httpx.get(url + "/api/health").json() == {"status": "ok"}
    finally:
        proc.kill()
        proc.wait(10)


def test_stopping_the_server_while_workers_warm_up_is_prompt_and_leaves_no_process(tmp_path):
    # The workers' warm-up is made to last a minute (a sitecustomize on the server's path wraps spark_core.warm_up),
    # so the bound below can leave room for a loaded machine while a shutdown that waited for the warm-up to end,
    # or left a warming worker behind, still fails.
    hook = tmp_path / "hook"
    hook.mkdir()
    (hook / "sitecustomize.py").write_text(
        "import time\n"
        "import spark_core\n"
        "_warm_up = spark_core.warm_up\n"
        "def _slow_warm_up():\n"
        "    open(" + repr(str(tmp_path / "warming")) + ", 'a').write('x')\n"
        "    _warm_up()\n"
        "    time.sleep(60)\n"
        "spark_core.warm_up = _slow_warm_up\n"
    )
    port, db, log = _free_port(), tmp_path / "stop.db", tmp_path / "stop.log"
    proc = _serve(port, db, log, pythonpath=hook)  # `spark serve` spawns its workers at start
    try:
        _wait_up(f"http://127.0.0.1:{port}", proc, log)
        for _ in range(600):  # a worker is inside its warm-up
            if (tmp_path / "warming").exists():
                break
            time.sleep(0.1)
        assert (tmp_path / "warming").exists(), "no worker started warming up:\n" + log.read_text()[-3000:]
        children = [
            int(p) for t in Path(f"/proc/{proc.pid}/task").iterdir() for p in (t / "children").read_text().split()
        ]
        proc.send_signal(signal.SIGTERM)
        proc.wait(30)  # far less than the minute the warm-up lasts: the lifespan does not wait for it
        time.sleep(1.0)
        assert children and not [c for c in children if _alive(c)]
    finally:
        proc.kill()
        proc.wait(10)
