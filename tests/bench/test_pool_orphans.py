"""A killed bench process takes its local pool workers with it (they would otherwise run on, orphaned)."""

from __future__ import annotations

import contextlib
import os
import signal
import subprocess
import sys
import textwrap
import time
from pathlib import Path

import pytest

SCRIPT = textwrap.dedent(
    """
    import os, sys, time
    from spark_core.bench.executors import run_jobs

    def job(path):
        with open(path, "w") as f:
            f.write(str(os.getpid()))
        time.sleep(120)
        return {}

    if __name__ == "__main__":
        run_jobs(job, [sys.argv[1] + "/a", sys.argv[1] + "/b"], workers=2)
    """
)


def _alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    with open(f"/proc/{pid}/stat") as f:  # a zombie is gone for our purpose
        return f.read().split(") ", 1)[1][0] != "Z"


@pytest.mark.parametrize("sig", [signal.SIGTERM, signal.SIGKILL])
def test_pool_workers_end_when_the_bench_process_is_killed(tmp_path: Path, sig: int):
    script = tmp_path / "bench.py"
    script.write_text(SCRIPT)
    parent = subprocess.Popen([sys.executable, str(script), str(tmp_path)], cwd=Path(__file__).parents[2])
    try:
        deadline = time.monotonic() + 60
        while not ((tmp_path / "a").exists() and (tmp_path / "b").exists()):
            assert time.monotonic() < deadline, "the pool never started its two jobs"
            time.sleep(0.1)
        time.sleep(0.2)
        workers = [int((tmp_path / n).read_text()) for n in ("a", "b")]
        assert all(_alive(w) for w in workers)
        parent.send_signal(sig)
        parent.wait(10)
        deadline = time.monotonic() + 15
        while any(_alive(w) for w in workers) and time.monotonic() < deadline:
            time.sleep(0.2)
        assert not any(_alive(w) for w in workers), "pool workers outlived the killed bench process"
    finally:
        parent.kill()
        for n in ("a", "b"):
            if (tmp_path / n).exists():
                with contextlib.suppress(ProcessLookupError, ValueError):
                    os.kill(int((tmp_path / n).read_text()), signal.SIGKILL)
