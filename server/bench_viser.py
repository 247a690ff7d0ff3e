"""Frame rate of the live 3D view while a trial executes (publisher updates per second of wall time)."""

from __future__ import annotations

import time

from spark_core.bench.report import footer


def run(task: str = "stack_three", seeds: int = 3) -> dict:
    from spark_core.bench.trial import PerceptionConfig, make_resolver
    from spark_core.execution import Executor
    from spark_core.execution.primitives import PrimitiveLibrary
    from spark_core.grammar import parse_plan
    from spark_core.sim.tasks import BUILTIN

    from .viser_scene import ViserScene

    scene = ViserScene(rate_hz=30.0)
    rates = []
    try:
        for seed in range(seeds):
            world = BUILTIN[task].make_world(seed)
            resolver = make_resolver(world, PerceptionConfig("sim"), seed)
            scene.show(world)
            t0, k0 = time.perf_counter(), scene.ticks
            Executor(PrimitiveLibrary(world, resolver, seed=seed), resolver).run(parse_plan(BUILTIN[task].reference_plan_text()))
            rates.append((scene.ticks - k0) / (time.perf_counter() - t0))
            scene.detach(world)
            world.close()
    finally:
        scene.stop()
    return {"task": task, "seeds": seeds, "fps_min": min(rates), "fps_mean": sum(rates) / len(rates), "target_hz": 30.0}


def section(r: dict, command: str) -> str:
    return (f"| view | target | mean | worst trial |\n|---|---|---|---|\n"
            f"| viser scene (robot links, objects, table) during {r['task']} | {r['target_hz']:.0f} Hz | "
            f"{r['fps_mean']:.1f} Hz | {r['fps_min']:.1f} Hz |\n\n"
            + footer(command, f"scene updates published per second of wall time while the trial executes (sim segmenter, "
                              f"rendering for perception in the same process), {r['seeds']} seeds; viser coalesces updates "
                              f"for slow clients"))
