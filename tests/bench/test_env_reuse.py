"""Env reuse across a task's trials in one process (sim.libero_envs): a world built on a reused LIBERO env starts
exactly where one on a freshly built env does, and a trial on it ends the same way (same verdict, simulated
time and events) on a deterministic cell."""

from __future__ import annotations

import numpy as np
import pytest

pytest.importorskip("libero", reason="benchmark extras: make bench-deps")

from spark_core.sim import libero_envs
from spark_core.sim.tasks import SUITES
from spark_core.trial import BaseSink, TrialConfig, run_trial

TASK = next(name for name in SUITES["liberopro"] if name.startswith("libero_object_swap:"))


def _state(world) -> dict[str, np.ndarray]:
    d, m = world.data, world.model
    return {
        "time": np.array([d.time]),
        **{k: getattr(d, k).copy() for k in ("qpos", "qvel", "act", "ctrl", "qacc_warmstart", "xpos", "mocap_pos")},
        "forcerange": m.actuator_forcerange.copy(),
    }


def test_a_reused_env_starts_where_a_fresh_one_does():
    spec = SUITES["liberopro"][TASK]
    libero_envs._spare.clear()
    first = spec.make_world(1, spec.embodiments[0])
    env = first.env
    first._limit_gripper_force("right", 5.0)  # what a grasp does to the model
    first._command_joints("right", first.q("right") + 0.2)
    first.settle(0.3)
    first.close()  # hands the env back
    reused = spec.make_world(2, spec.embodiments[0])
    try:
        assert reused.env is env  # it was reused, not rebuilt
        got, frame = _state(reused), reused.render("agentview", 160, 120)
        rgb = frame.rgb
    finally:
        reused.close()
    libero_envs._spare.clear()
    fresh = spec.make_world(2, spec.embodiments[0])
    try:
        assert fresh.env is not env
        want, fresh_frame = _state(fresh), fresh.render("agentview", 160, 120)
        fresh_rgb = fresh_frame.rgb
    finally:
        fresh.close()
        libero_envs._spare.clear()
    for k in want:
        np.testing.assert_array_equal(got[k], want[k], err_msg=k)
    np.testing.assert_array_equal(frame.depth_m, fresh_frame.depth_m)
    np.testing.assert_array_equal(frame.object_ids, fresh_frame.object_ids)
    np.testing.assert_array_equal(rgb, fresh_rgb)


class _Record(BaseSink):
    def __init__(self):
        self.events: list[tuple[str, str]] = []
        self.env = None

    def on_start(self, ctx):
        self.env = ctx.world.env  # held: another env cannot take its place at the same address

    def on_event(self, event):
        self.events.append((event.node_path, event.kind))


def _trial(seed: int):
    rec = _Record()
    out = run_trial(TrialConfig(TASK, planner="rules", segmenter="sim", seed=seed), [rec])
    return out, rec


def test_a_trial_on_a_reused_env_ends_as_on_a_fresh_one():
    libero_envs._spare.clear()
    fresh, fresh_rec = _trial(1)
    _trial(0)  # the same env, another init state in between
    again, again_rec = _trial(1)
    libero_envs._spare.clear()
    assert again_rec.env is fresh_rec.env  # the second run of init state 1 ran on the reused env
    assert fresh.verdict.value != "crashed", fresh.reason
    assert (again.verdict, again.sim_time_s, again.plan_text) == (fresh.verdict, fresh.sim_time_s, fresh.plan_text)
    assert again_rec.events == fresh_rec.events


def test_a_task_change_frees_the_previous_tasks_env():
    """One spare per process: when a worker moves on to another task, the spare it will never take back is closed
    (its MuJoCo model and data freed); only dropping it leaked 300-500 MB per task until workers ran out of memory."""
    other = next(name for name in SUITES["liberopro"] if name.startswith("libero_spatial_swap:"))
    libero_envs._spare.clear()
    first = SUITES["liberopro"][TASK].make_world(0, SUITES["liberopro"][TASK].embodiments[0])
    old_env = first.env
    first.close()  # hands its env back as the spare
    assert len(libero_envs._spare) == 1
    second = SUITES["liberopro"][other].make_world(0, SUITES["liberopro"][other].embodiments[0])
    try:
        assert second.env is not old_env
        assert old_env.sim is None  # closed: robosuite freed its sim
        assert getattr(old_env, "_spark_release", None) is None  # the hook that kept it alive is gone
    finally:
        second.close()
    assert len(libero_envs._spare) == 1 and old_env not in [e.env for e in libero_envs._spare.values()]
