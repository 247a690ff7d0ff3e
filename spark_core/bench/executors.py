"""Where a batch's trials run: a local process pool (the default), or Ray, either a local cluster started for
the batch or an existing cluster at an address (evaluation beyond one machine). Results stream back in
completion order to `progress`; the returned list is in job order, one row per job.

On Ray nothing is lost: a job whose worker process or node dies is run again (up to RAY_RETRIES times) on what
is left of the cluster. A job must therefore be idempotent: the bench's jobs carry a trial id decided before
submission, and the trace store's `begin_attempt` makes a retry overwrite its own record, so every trial ends up
stored exactly once. An exception raised by the job itself is a result, not a crash: it is not retried."""

from __future__ import annotations

import multiprocessing
import os
import threading
import time
from collections.abc import Callable, Sequence
from concurrent.futures import ProcessPoolExecutor, as_completed
from typing import Any

EXECUTORS = ("local", "ray")
RAY_RETRIES = 3  # a worker or node lost mid-job: run the job again, at most this many times
PARENT_POLL_S = 1.0  # how often a pool worker checks that the process that started it is still alive


def run_jobs(
    fn: Callable[[Any], dict],
    jobs: Sequence[Any],
    executor: str = "local",
    workers: int = 1,
    ray_address: str | None = None,
    progress: Callable[[dict], None] | None = None,
) -> list[dict]:
    """`fn(job) -> row` for every job. `fn` must be a module-level function (it is pickled to the workers)."""
    if executor not in EXECUTORS:
        raise ValueError(f"unknown executor {executor!r}; available: {', '.join(EXECUTORS)}")
    results: list[dict | None] = [None] * len(jobs)

    def done(i: int, row: dict) -> None:
        results[i] = row
        if progress:
            progress(row)

    if executor == "ray":
        _run_ray(fn, jobs, workers, ray_address, done)
    elif workers <= 1:
        for i, job in enumerate(jobs):
            done(i, fn(job))
    else:
        # spawn, never fork: the caller may hold threads (a console, torch's pool) whose locks a fork would copy held
        with ProcessPoolExecutor(
            workers,
            mp_context=multiprocessing.get_context("spawn"),
            initializer=exit_with_parent,
            initargs=(os.getpid(),),
        ) as pool:
            futures = {pool.submit(fn, job): i for i, job in enumerate(jobs)}
            for fut in as_completed(futures):
                done(futures[fut], fut.result())
    return results  # type: ignore[return-value]


def exit_with_parent(parent_pid: int) -> None:
    """Pool-worker initializer: end this worker when the process that started the pool is gone. A killed
    `spark bench` (SIGTERM, SIGKILL, OOM) otherwise leaves its workers running its trials on an orphaned pool,
    holding both cores and gigabytes for nobody."""

    def watch() -> None:
        while os.getppid() == parent_pid:
            time.sleep(PARENT_POLL_S)
        os._exit(1)

    threading.Thread(target=watch, name="exit-with-parent", daemon=True).start()


def _run_ray(fn, jobs, workers: int, address: str | None, done: Callable[[int, dict], None]) -> None:
    try:
        import ray
    except ImportError:
        raise RuntimeError(
            "the ray executor needs the `ray` package: make install (it is pinned in requirements.lock)"
        ) from None
    started = not ray.is_initialized()
    if started:
        # A local cluster sized to `workers` CPUs, or join an existing one. Workers inherit this environment
        # (MUJOCO_GL, HF_HUB_OFFLINE) so rendering and the offline text model work there too.
        env = {k: v for k, v in os.environ.items() if k in ("MUJOCO_GL", "HF_HUB_OFFLINE", "PYTHONPATH")}
        ray.init(
            address=address,
            num_cpus=None if address else max(workers, 1),
            include_dashboard=False,
            log_to_driver=False,
            configure_logging=False,
            runtime_env={"env_vars": env},
        )
    try:
        from ray.exceptions import NodeDiedError, WorkerCrashedError

        remote = ray.remote(num_cpus=1, max_retries=RAY_RETRIES, retry_exceptions=False)(fn)
        pending = {remote.remote(job): i for i, job in enumerate(jobs)}
        while pending:
            ready, _ = ray.wait(list(pending), num_returns=1)
            ref = ready[0]
            i = pending.pop(ref)
            try:
                row = ray.get(ref)
            except (WorkerCrashedError, NodeDiedError) as e:
                raise RuntimeError(
                    f"job {i} lost its Ray worker {RAY_RETRIES + 1} times (the cluster is losing workers or nodes): {e}"
                ) from None
            done(i, row)
    finally:
        if started:
            ray.shutdown()
