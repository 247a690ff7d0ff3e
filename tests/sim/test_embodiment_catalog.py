"""Every embodiment a task names is in the catalog, with the arms its world has: a submitted plan's arm tags are
checked against the catalog's arms (server/api/arms.py), and an embodiment it did not list (the robots the CaP-Bench
and LIBERO-PRO envs come with) was not checked at all. Read from the task and env definitions: no world is built."""

from __future__ import annotations

import inspect

import pytest

from spark_core.catalog import ALL_EMBODIMENTS, BENCHMARK_EMBODIMENTS, EMBODIMENTS
from spark_core.sim import embodiments as scene_embodiments
from spark_core.sim.capbench_envs import ENVS
from spark_core.sim.robosuite_world import arm_indices
from spark_core.sim.tasks import SUITES, TASKS


def test_every_task_runs_on_embodiments_the_catalog_lists():
    missing = {name: e for name, t in TASKS.items() for e in t.embodiments if e not in ALL_EMBODIMENTS}
    assert missing == {}


def test_the_scene_builders_set_ups_have_the_catalogs_arms():
    assert set(EMBODIMENTS) == set(scene_embodiments.EMBODIMENTS)
    for name, entry in EMBODIMENTS.items():
        assert entry.suite is None
        assert set(entry.arms) == set(scene_embodiments.robots_for(name)), name


def test_a_benchmark_robot_runs_its_own_suites_tasks_and_nothing_else():
    """So `spark bench embodiments` and `spark run --embodiment` (which offer EMBODIMENTS) never offer one, and the
    console's robot choice (the catalog's embodiments a task lists) offers one only for its own tasks."""
    assert not set(EMBODIMENTS) & set(BENCHMARK_EMBODIMENTS)
    for suite, tasks in SUITES.items():
        for name, task in tasks.items():
            for e in task.embodiments:
                assert ALL_EMBODIMENTS[e].suite in (None if suite in ("builtin", "bimanual") else suite,), (name, e)


def test_capbench_embodiments_have_their_envs_arms():
    for name, task in SUITES["capbench"].items():
        (embodiment,) = task.embodiments
        assert ALL_EMBODIMENTS[embodiment].arms == tuple(arm_indices(len(ENVS[name].robots))), name
    assert SUITES["capbench"]["TwoArmLift"].embodiments == ("robosuite-two-pandas",)
    assert SUITES["capbench"]["Lift"].embodiments == ("robosuite-panda",)


def test_liberopro_embodiment_has_its_envs_arms():
    pytest.importorskip("libero", reason="benchmark extras: make bench-deps")
    from spark_core.sim import libero_envs

    libero_envs._configure()  # LIBERO asks for its paths on import otherwise
    from libero.libero.envs.env_wrapper import ControlEnv

    # build_control_env passes no robots: the env's default
    assert "robots" not in inspect.signature(libero_envs.build_control_env).parameters
    robots = inspect.signature(ControlEnv.__init__).parameters["robots"].default
    assert SUITES["liberopro"], "LIBERO-PRO task files absent"
    for name, task in SUITES["liberopro"].items():
        (embodiment,) = task.embodiments
        assert ALL_EMBODIMENTS[embodiment].arms == tuple(arm_indices(len(robots))), name
