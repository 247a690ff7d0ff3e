"""Frame rate of the live 3D view while trials execute, through the console's real path: the trial runs in a
worker process, its SceneFeed streams poses over the pipe, the console draws them into viser."""

from __future__ import annotations

import tempfile
import time

from spark_core.bench.report import footer


def run(task: str = "stack_three", seeds: int = 3) -> dict:
    from server.trials.runner import TrialRunner
    from server.view3d.viser_scene import ViserScene
    from spark_core import TraceStore, TrialConfig

    scene = ViserScene(rate_hz=30.0)
    rates = []
    with tempfile.TemporaryDirectory() as tmp:
        store = TraceStore(f"sqlite:///{tmp}/bench.db")
        runner = TrialRunner(store, workers=1, scene=scene, artifacts_dir=f"{tmp}/art", spawn_at_start=True)
        try:
            for seed in range(seeds):
                tid = f"viser-bench-{seed}"
                runner.submit(tid, TrialConfig(task, segmenter="sim", seed=seed).check())
                while (store.get_trial(tid) or {}).get("status") == "queued":
                    time.sleep(0.005)
                t0, k0 = time.perf_counter(), scene.ticks
                while store.get_trial(tid)["status"] == "running":
                    time.sleep(0.05)
                trial = store.get_trial(tid)
                if not trial["success"]:
                    raise RuntimeError(f"benchmark trial {tid} failed: {trial['reason']}")
                rates.append((scene.ticks - k0) / (time.perf_counter() - t0))
        finally:
            runner.shutdown()
            scene.stop()
    return {"task": task, "seeds": seeds, "fps_min": min(rates), "fps_mean": sum(rates) / len(rates), "target_hz": 30.0}


def section(r: dict, command: str) -> str:
    return (
        f"| view | target | mean | worst trial |\n|---|---|---|---|\n"
        f"| viser scene (robot links, objects, table, target pose) during {r['task']} | {r['target_hz']:.0f} Hz | "
        f"{r['fps_mean']:.1f} Hz | {r['fps_min']:.1f} Hz |\n\n"
        + footer(
            command,
            f"pose updates drawn per second of wall time while the trial runs (sim segmenter); the "
            f"trial runs in a worker process and streams poses to the console over a pipe; "
            f"{r['seeds']} seeds; viser coalesces updates for slow clients",
        )
    )
