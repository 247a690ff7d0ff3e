"""A real two-node Ray cluster on this machine for tests: `ray start --head` and a second `ray start --address`,
each with one CPU, in a temporary directory of their own (so no other Ray on the machine is touched or joined).

Processes are found through /proc: the cluster's own (their command line names its temp dir) and their children
(Ray's workers, titled `ray::<function>` while they run a task). Only those are ever killed."""

from __future__ import annotations

import contextlib
import os
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import time
from pathlib import Path

RAY = str(Path(sys.executable).with_name("ray"))
# Token auth off on every side (a ~/.ray/auth_token left by someone else would otherwise make nodes disagree);
# fast node-death detection so a killed node's trials are retried within seconds.
ENV = {
    "RAY_AUTH_MODE": "disabled",
    "RAY_USAGE_STATS_ENABLED": "0",
    "RAY_health_check_period_ms": "500",
    "RAY_health_check_timeout_ms": "1000",
    "RAY_health_check_failure_threshold": "3",
}


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


def _processes() -> dict[int, tuple[int, str]]:
    """pid -> (parent pid, command line) of every process we can read."""
    out = {}
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            cmd = Path(f"/proc/{entry}/cmdline").read_bytes().replace(b"\0", b" ").decode(errors="replace")
            fields = Path(f"/proc/{entry}/stat").read_text().rsplit(")", 1)[1].split()
        except (OSError, IndexError):
            continue
        if fields[0] != "Z":  # zombies are already dead
            out[int(entry)] = (int(fields[1]), cmd)
    return out


class RayCluster:
    def __init__(self) -> None:
        self.dir = Path(tempfile.mkdtemp(prefix="rayt-", dir="/tmp"))  # short: Ray's socket paths must fit 107 chars
        self.port = _free_port()
        self.node2_port = _free_port()
        self.env = {**os.environ, **ENV}

    @property
    def address(self) -> str:
        return f"127.0.0.1:{self.port}"

    def _ray(self, *args: str) -> None:
        done = subprocess.run([RAY, *args], env=self.env, capture_output=True, text=True, timeout=120)
        if done.returncode != 0:
            raise RuntimeError(f"ray {' '.join(args)} failed: {done.stderr[-2000:]}")

    def start(self) -> RayCluster:
        common = ["--num-cpus=1", "--disable-usage-stats", f"--temp-dir={self.dir}"]
        self._ray(
            "start",
            "--head",
            f"--port={self.port}",
            "--include-dashboard=false",
            f"--dashboard-agent-listen-port={_free_port()}",
            *common,
        )
        self.start_node2()
        return self

    def start_node2(self) -> None:
        self._ray(
            "start",
            f"--address={self.address}",
            f"--node-manager-port={self.node2_port}",
            f"--dashboard-agent-listen-port={_free_port()}",
            "--num-cpus=1",
            "--disable-usage-stats",
        )

    def _ours(self) -> dict[int, tuple[int, str]]:
        """The cluster's processes and all their descendants (never this test process)."""
        procs = _processes()
        ours = {p for p, (_, cmd) in procs.items() if str(self.dir) in cmd and p != os.getpid()}
        grew = True
        while grew:
            more = {p for p, (parent, _) in procs.items() if parent in ours and p not in ours}
            ours |= more
            grew = bool(more)
        return {p: procs[p] for p in ours}

    def trial_workers(self, function: str = "_one") -> list[int]:
        """Pids of this cluster's workers running `function` right now."""
        return [p for p, (_, cmd) in self._ours().items() if cmd.strip() == f"ray::{function}"]

    def kill_trial_workers(self, function: str = "_one") -> list[int]:
        """SIGKILL every worker of this cluster running `function` right now; their pids."""
        pids = self.trial_workers(function)
        for p in pids:
            _kill(p)
        return pids

    def kill_node2(self) -> list[int]:
        """SIGKILL the second node's raylet and everything under it (its workers): the node is gone."""
        procs = self._ours()
        raylet = [p for p, (_, cmd) in procs.items() if f"--node_manager_port={self.node2_port}" in cmd]
        victims = set(raylet)
        grew = True
        while grew:
            more = {p for p, (parent, _) in procs.items() if parent in victims and p not in victims}
            victims |= more
            grew = bool(more)
        for p in victims:
            _kill(p)
        return sorted(victims)

    def stop(self) -> None:
        for p in self._ours():
            _kill(p)
        time.sleep(0.5)
        shutil.rmtree(self.dir, ignore_errors=True)


def _kill(pid: int) -> None:
    with contextlib.suppress(ProcessLookupError):
        os.kill(pid, signal.SIGKILL)
