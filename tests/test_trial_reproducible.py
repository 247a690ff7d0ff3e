"""A trial's simulated run depends only on its configuration and seed: not on the machine's load, thread scheduling
or what the process ran before.

The case that showed it was not so: LIBERO-PRO's spatial swap, "pick up the black bowl on the stove and place it on
the plate", seed 1, rules planner, sim segmenter, ran 8.90 / 8.92 / 8.93 s simulated (once past the 11 s limit):
LIBERO placed its fixtures (the stove) from numpy's unseeded global generator at every reset, and an init state
does not hold them. `sim.libero_envs.make_env` seeds that reset with the init index."""

from __future__ import annotations

import threading

import numpy as np
import pytest

pytest.importorskip("libero", reason="benchmark extras: make bench-deps")

from spark_core.sim import libero_envs
from spark_core.trial import BaseSink, TrialConfig, run_trial

TASK = "libero_spatial_swap:pick_up_the_black_bowl_on_the_stove_and_place_it_on_the_plate"


def _placement(env) -> dict[str, np.ndarray]:
    """What a reset decides: fixtures live in the model (body_pos, body_quat), objects and the arm in the data."""
    m, d = env.env.sim.model._model, env.env.sim.data._data
    return {
        "body_pos": m.body_pos.copy(),
        "body_quat": m.body_quat.copy(),
        "qpos": d.qpos.copy(),
        "qvel": d.qvel.copy(),
        "time": np.array([d.time]),
    }


def test_a_libero_reset_places_everything_by_the_init_index_alone():
    """The same init index gives the same scene, fixtures included, whatever numpy's global generator held before
    (another trial's draws, a fresh process), on a fresh env and on a reused one; the caller's generator is left
    as it was."""
    task = next(t for t in libero_envs.tasks() if t.name == TASK)
    libero_envs._spare.clear()
    np.random.seed(7)
    before = np.random.get_state()
    env = libero_envs.make_env(task, 1, reuse=False)
    try:
        after = np.random.get_state()
        first = _placement(env)
        np.random.seed(12345)  # another history of the global generator: a new process, or other trials before
        np.random.uniform(size=101)
        env.env._spark_release()  # handed back, as a closing world does: the next make_env resets the same env
        again = libero_envs.make_env(task, 1)
        assert again is env
        second = _placement(again)
    finally:
        libero_envs._spare.clear()
        env.close()
    for k in first:
        np.testing.assert_array_equal(second[k], first[k], err_msg=k)
    assert after[0] == before[0] and np.array_equal(after[1], before[1]) and after[2:] == before[2:]


class _Fingerprint(BaseSink):
    """What the trial did in simulated time: events (node, kind, simulated time, outcome details), groundings,
    the recorded joint trajectory and where every object ended."""

    def __init__(self):
        self.events: list[tuple] = []
        self.final: dict[str, object] = {}

    def on_event(self, event):
        detail = {k: v for k, v in event.detail.items() if k in ("attempts", "sim_time_s", "failure", "reason")}
        self.events.append((event.node_path, str(event.kind), round(event.t_sim or 0.0, 4), detail))

    def on_finish(self, ctx, outcome):
        world = ctx.world
        self.final = {
            "trajectory": [(round(t, 4), arm, q, g) for t, arm, q, g in world.recorder.rows],
            "objects": {label: world.body_position(o.body).copy() for label, o in world.scene.objects.items()},
            "groundings": [
                (g["label"], g["t_sim_s"], (g.get("keypoint") or {}).get("position_m")) for g in ctx.resolver.groundings
            ],
        }


def _run(load: bool):
    fp = _Fingerprint()
    stop = threading.Event()

    def burn() -> None:  # holds the GIL as much as it can: every other thread of the trial runs late
        while not stop.is_set():
            sum(range(5000))

    burner = threading.Thread(target=burn, daemon=True)
    if load:
        burner.start()
    try:
        out = run_trial(TrialConfig(TASK, seed=1, planner="rules", segmenter="sim"), [fp])
    finally:
        stop.set()
        if load:
            burner.join()
    return out, fp


@pytest.mark.slow
def test_the_same_trial_runs_the_same_on_a_loaded_machine():
    """One LIBERO-PRO trial twice in one process (the second on the first's reused env, with a thread burning CPU
    beside it): the same verdict, simulated time, events, groundings, trajectory and final object positions."""
    libero_envs._spare.clear()
    try:
        quiet, a = _run(load=False)
        busy, b = _run(load=True)
    finally:
        libero_envs._spare.clear()
    assert quiet.verdict.value != "crashed", quiet.reason
    assert (busy.verdict, busy.sim_time_s, busy.plan_text, busy.retries) == (
        quiet.verdict,
        quiet.sim_time_s,
        quiet.plan_text,
        quiet.retries,
    )
    assert b.events == a.events
    assert b.final["groundings"] == a.final["groundings"]
    assert b.final["trajectory"] == a.final["trajectory"]
    for label, pos in a.final["objects"].items():
        np.testing.assert_allclose(b.final["objects"][label], pos, atol=1e-6, err_msg=label)
