"""Replay a finished trial in the 3D view from its recorded scene states (qpos every 40 ms of simulated time).
The scene is rebuilt from the task and seed (scene construction is deterministic), then only forward
kinematics runs: no physics, so a replay shows exactly what was recorded."""

from __future__ import annotations

import threading
import time

import numpy as np


class ReplayUnavailable(Exception):
    """The trial cannot be replayed (still running, no recorded states, or its task no longer exists)."""


def start_replay(store, scene, trial_id: str, speed: float = 1.0) -> dict:
    """Start replaying on a thread; raises KeyError for an unknown trial, ReplayUnavailable with the reason."""
    from spark_core import TASKS

    trial = store.get_trial(trial_id)
    if trial is None:
        raise KeyError(trial_id)
    if trial["status"] != "done":
        raise ReplayUnavailable(f"trial {trial_id!r} is {trial['status']}: replay needs a finished trial")
    states = store.scene_states(trial_id)
    if not states:
        raise ReplayUnavailable(
            f"trial {trial_id!r} has no recorded scene states (recorded before replay existed, "
            f"or it ended before the robot moved)"
        )
    task = TASKS.get(trial["task"])
    if task is None:
        raise ReplayUnavailable(f"trial {trial_id!r} ran task {trial['task']!r}, which this build does not have")
    keypoints = {g["label"]: g["keypoint"]["position_m"] for g in trial.get("groundings", []) if g.get("keypoint")}
    key = f"replay:{trial_id}"
    world = task.make_world(trial["seed"])
    if len(states[0][1]) != world.model.nq:
        world.close()
        raise ReplayUnavailable(
            f"trial {trial_id!r} was recorded with a different scene model "
            f"({len(states[0][1])} vs {world.model.nq} joint coordinates)"
        )
    threading.Thread(
        target=_play,
        args=(scene, key, trial_id, world, states, keypoints, speed),
        name=f"replay-{trial_id}",
        daemon=True,
    ).start()
    return {
        "id": trial_id,
        "key": key,
        "states": len(states),
        "speed": speed,
        "duration_s": round(states[-1][0] - states[0][0], 3),
    }


def _play(scene, key: str, trial_id: str, world, states: list, keypoints: dict, speed: float) -> None:
    import mujoco

    from spark_core import body_poses, visual_geoms

    m = world.model
    d = mujoco.MjData(m)
    origin = np.asarray(getattr(world, "origin_m", np.zeros(3)), float)  # robosuite/LIBERO: not MuJoCo's origin
    try:
        scene.show(key, visual_geoms(m), title=f"replay of {trial_id}")
        scene.markers(key, keypoints)
        t0, start, shown = states[0][0], time.monotonic(), -1.0
        for t, qpos in states:
            delay = (t - t0) / speed - (time.monotonic() - start)
            if delay > 0:
                time.sleep(delay)
            if scene.current != key:
                return  # a live trial (or another replay) took over the view
            xpos, xquat = body_poses(m, d, np.asarray(qpos, float))
            scene.update(key, xpos - origin, xquat)  # in the world's frame, like the live view and the keypoints
            if t - shown >= 0.5:
                scene.active(key, f"**Replay:** {trial_id}  \nt = {t:.1f} / {states[-1][0]:.1f} s (simulated)")
                shown = t
        scene.active(key, f"**Replay:** {trial_id}  \nfinished ({states[-1][0]:.1f} s simulated)")
    finally:
        world.close()
