"""Control and simulator benchmarks: IK success and solve time, real-time factor, camera frame cost."""

from __future__ import annotations

import statistics
import time

import numpy as np

from ..control.ik import Unreachable, solve_ik
from ..control.kinematics import ArmKinematics
from ..control.panda import panda
from .report import footer, pct


def ik_benchmark(n_targets: int = 200, restarts: int = 10, seed: int = 0) -> dict:
    """Targets are FK of uniformly random joint configurations 0.05 rad inside the limits (reachable by
    construction), keeping only TCP positions above the table (z > 0) and outside the robot's own base column
    (r > 0.15 m): the workspace a task can ask for. Each solve starts from the home configuration."""
    robot = panda()
    kin = ArmKinematics(robot)
    rng = np.random.default_rng(seed)
    times, solved, used = [], 0, []
    for _ in range(n_targets):
        while True:
            target = kin.fk(rng.uniform(kin.lower + 0.05, kin.upper - 0.05))
            if target.position_m[2] > 0.0 and np.linalg.norm(target.position_m[:2]) > 0.15:
                break
        t0 = time.perf_counter()
        try:
            res = solve_ik(kin, target, robot.home_q_rad, restarts=restarts, rng=rng)
            solved += 1
            used.append(res.restarts)
        except Unreachable:
            pass
        times.append(time.perf_counter() - t0)
    times_ms = np.array(times) * 1000
    return {
        "targets": n_targets,
        "solved": solved,
        "rate": solved / n_targets,
        "median_ms": float(np.median(times_ms)),
        "p99_ms": float(np.percentile(times_ms, 99)),
        "first_try": used.count(0),
        "restarts": restarts,
    }


def speed_benchmark(task: str = "stack_three", seeds: int = 3, frames: int = 10) -> dict:
    from ..sim.tasks import BUILTIN
    from ..trial import TrialConfig, run_trial

    rtf = []
    for s in range(seeds):
        out = run_trial(TrialConfig(task, segmenter="privileged-keypoints", seed=s))
        rtf.append(out.sim_time_s / out.wall_time_s)
    world = BUILTIN[task].make_world(0)
    world.render("agentview")  # warm-up: context creation
    cost = []
    for _ in range(frames):
        t0 = time.perf_counter()
        world.render("agentview", 640, 480)
        cost.append(time.perf_counter() - t0)
    world.close()
    return {
        "task": task,
        "rtf_median": statistics.median(rtf),
        "rtf_min": min(rtf),
        "frame_ms_median": 1000 * statistics.median(cost),
    }


def ik_section(r: dict, command: str) -> str:
    return (
        f"| targets | solved (≤ {r['restarts']} restarts) | solved from the seed alone | median solve | p99 solve |\n"
        f"|---|---|---|---|---|\n| {r['targets']} | {pct(r['rate'])} | {pct(r['first_try'] / r['targets'])} | "
        f"{r['median_ms']:.2f} ms | {r['p99_ms']:.2f} ms |\n\n"
        + footer(
            command,
            "Panda (example-robot-data URDF) in pinocchio, damped least squares, full 6-D pose targets "
            "from FK of uniform random joint configurations 0.05 rad inside the limits, TCP above the "
            "table and > 15 cm from the base axis; every solve seeded from home",
        )
    )


def speed_section(r: dict, command: str) -> str:
    return (
        f"| measure | value |\n|---|---|\n"
        f"| real-time factor, {r['task']} reference plan, no rendering (median of seeds) | {r['rtf_median']:.1f}× |\n"
        f"| real-time factor, worst seed | {r['rtf_min']:.1f}× |\n"
        f"| one 640×480 RGB + depth + segmentation frame (agentview, EGL on CPU) | {r['frame_ms_median']:.0f} ms |\n\n"
        + footer(
            command,
            "MuJoCo 3.3.7, 2 ms physics step, 10 ms control period, one process on one core; "
            "segmenter privileged-keypoints (PRIVILEGED, no cameras), so no rendering inside the trial",
        )
    )
