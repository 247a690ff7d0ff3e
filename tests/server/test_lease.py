"""Issue 20, finding 6: one server per store (a lease), so a second console never marks the first one's live
trials interrupted; and trials queued but never started survive a restart, run as they were asked for."""

import subprocess
import time

import pytest
from fastapi.testclient import TestClient

from server.app import create_app
from server.settings import Settings
from spark_core import LeaseHeld, StoreLease, TraceStore, TrialConfig, config_record
from spark_core.perception.noisy_segmenter import NoiseModel

from .test_api import wait_done
from .test_faults import _paused_trial


def _app(db, tmp_path, **kw):
    return create_app(
        Settings(store_url=f"sqlite:///{db}", workers=1, viser=False, artifacts_dir=str(tmp_path / "art"), **kw)
    )


def test_a_second_console_on_the_same_store_refuses_to_start_and_touches_no_trial(tmp_path):
    import os

    db = tmp_path / "one.db"
    with TestClient(_app(db, tmp_path)) as first:
        trial = _paused_trial(first)
        with pytest.raises(LeaseHeld) as held, TestClient(_app(db, tmp_path)):
            pass
        assert f"process {os.getpid()} on" in str(held.value) and "in use by another SPARK console" in str(held.value)
        # the first console's trial is untouched: still running, still live, and it finishes when resumed
        assert first.get(f"/api/trials/{trial['id']}").json()["status"] == "running"
        with pytest.raises(LeaseHeld):  # nor may anything else interrupt it while the lease is live
            TraceStore(f"sqlite:///{db}").interrupt_unfinished()
        first.post(f"/api/trials/{trial['id']}/control", json={"action": "resume"})
        assert wait_done(first, trial["id"])["verdict"] == "success"
    # released on shutdown: the next console starts
    with TestClient(_app(db, tmp_path)) as again:
        assert again.get("/api/health").json() == {"status": "ok"}


def test_a_lease_left_by_a_dead_server_is_taken_over_and_its_running_trials_interrupted(tmp_path):
    db = tmp_path / "dead.db"
    store = TraceStore(f"sqlite:///{db}")
    dead = subprocess.Popen(["true"])
    dead.wait()
    lease = StoreLease(store)
    lease.pid = dead.pid  # what a server killed with SIGKILL leaves: its row, a fresh heartbeat, no process
    lease.acquire()
    store.create_trial("was-running", status="running", task="lift_block")
    with TestClient(_app(db, tmp_path)) as c:
        after = c.get("/api/trials/was-running").json()
        assert after["status"] == "interrupted" and after["verdict"] == "interrupted"
        assert "server stopped while the trial was running" in after["reason"]
        holder = c.app.state.lease.holder()  # type: ignore[attr-defined]
        assert holder is not None and holder.owner == c.app.state.lease.owner  # type: ignore[attr-defined]


def test_a_stale_heartbeat_frees_the_lease(tmp_path):
    store = TraceStore(f"sqlite:///{tmp_path / 's.db'}")
    first = StoreLease(store, stale_after_s=0.5)
    first.pid, first.host = 1, "another-host"  # alive as far as we can tell: only its heartbeat can go stale
    first.acquire()
    second = StoreLease(store, stale_after_s=0.5)
    with pytest.raises(LeaseHeld, match="another-host"):
        second.acquire()
    time.sleep(0.7)
    assert second.acquire() is not None and not first.renew()  # taken over; the first learns it lost it


def test_queued_trials_survive_a_restart_and_run_as_asked(tmp_path):
    db = tmp_path / "queue.db"
    with TestClient(_app(db, tmp_path)) as c:
        running = _paused_trial(c)  # holds the only worker
        queued = c.post(
            "/api/trials", json={"task": "lift_block", "segmenter": "privileged-keypoints", "seed": 7}
        ).json()["id"]
        assert c.get(f"/api/trials/{queued}").json()["status"] == "queued"
    # a graceful stop: the running trial is recorded interrupted, the queued one stays queued
    store = TraceStore(f"sqlite:///{db}")
    assert store.get_trial(running["id"])["verdict"] == "interrupted"
    assert store.get_trial(queued)["status"] == "queued"
    # a trial queued with settings the API cannot express (sim-noisy's noise model) comes back with them, exactly
    noise = NoiseModel(miss_rate=0.0, erode_px=1, confusion_rate=0.0, depth_noise_m=0.002)
    noisy = TrialConfig("lift_block", segmenter="sim-noisy", noise=noise, seed=3)
    store.create_trial("noisy-1", status="queued", task="lift_block", protocol={"config": config_record(noisy)})
    store.create_trial("old-1", status="queued", task="lift_block", protocol={"config": {"task": "no_such_task"}})
    with TestClient(_app(db, tmp_path)) as c:
        again = wait_done(c, queued)
        assert again["verdict"] == "success" and again["seed"] == 7
        ran = wait_done(c, "noisy-1")
        assert ran["protocol"]["noise"] == noise.describe() and ran["segmenter"] == "sim-noisy"
        lost = c.get("/api/trials/old-1").json()
        assert lost["verdict"] == "interrupted" and "cannot be queued again" in lost["reason"]
        assert "no_such_task" in lost["reason"]
