"""Parallel branches on a simulated world take turns (execution/turns.py): the branches' interleaving, and so the
simulated run, depends on the plan alone, not on how fast each thread happens to run; sync_barrier's timeout is
simulated seconds."""

from __future__ import annotations

import random
import threading
import time

from spark_core.execution import ActionOutcome, Executor, FailureKind
from spark_core.grammar import parse_plan

CONTROL_DT_S = 0.01

PLAN = """
task: two arms, each its own way
tree:
  type: sequence
  children:
    - type: parallel
      children:
        - type: sequence
          arm: left
          children:
            - primitive: wait
              params: {duration: 0.05}
            - primitive: sync_barrier
              params: {name: meet}
            - primitive: wait
              params: {duration: 0.08}
        - type: sequence
          arm: right
          children:
            - primitive: wait
              params: {duration: 0.12}
            - primitive: sync_barrier
              params: {name: meet}
            - primitive: wait
              params: {duration: 0.03}
    - primitive: wait
      arm: left
      params: {duration: 0.02}
"""


class TickWorld:
    """A world whose clock moves one control period per tick of whichever arm ticks, calling its monitors after
    each, as MujocoWorld does (under its lock)."""

    def __init__(self) -> None:
        self._lock = threading.RLock()
        self.monitors: list = []
        self.sim_time_s = 0.0
        self.log: list[tuple[str, float]] = []  # (arm, simulated time after its tick)

    def tick(self, arm: str) -> None:
        with self._lock:
            self.sim_time_s = round(self.sim_time_s + CONTROL_DT_S, 6)
            self.log.append((arm, self.sim_time_s))
            for monitor in self.monitors:
                monitor(self)


class TickArms:
    """Two arms whose `wait` ticks the world once per control period; `jitter` sleeps a random wall time before
    ticks (a loaded machine, a slow IK solve), which must change nothing simulated."""

    arms = ("left", "right")

    def __init__(self, world: TickWorld, jitter: random.Random | None = None) -> None:
        self.world = world
        self.jitter = jitter

    def perform(self, call, keypoints, arm, timeout_s) -> ActionOutcome:
        t0 = self.world.sim_time_s
        for _ in range(round(call.args["duration"] / CONTROL_DT_S)):
            if self.jitter is not None and self.jitter.random() < 0.5:
                time.sleep(self.jitter.uniform(0.0, 0.004))
            self.world.tick(arm)
        return ActionOutcome.success(self.world.sim_time_s - t0)


class NoPerception:
    def resolve(self, label):
        raise AssertionError("no labels in these plans")

    def refresh(self) -> None:
        pass


def run(plan: str, jitter: random.Random | None = None):
    world = TickWorld()
    result = Executor(TickArms(world, jitter), NoPerception()).run(parse_plan(plan))
    events = [(e.node_path, e.kind, e.t_sim) for e in result.events]
    return world, result, events


def test_branches_interleave_the_same_way_however_fast_their_threads_run():
    quiet_world, quiet, quiet_events = run(PLAN)
    assert quiet.outcome == "success", quiet.reason
    for seed in (1, 2, 3):
        world, result, events = run(PLAN, random.Random(seed))
        assert result.outcome == "success", result.reason
        assert world.log == quiet_world.log
        assert events == quiet_events
    # one control period each, in branch order, while both move; the barrier holds left until right arrives
    assert quiet_world.log[:10] == [("left" if i % 2 == 0 else "right", round(0.01 * (i + 1), 2)) for i in range(10)]
    right_at_barrier = [t for p, k, t in quiet_events if p.endswith("children[1].children[1]") and k == "succeeded"]
    left_after = [t for p, k, t in quiet_events if p.endswith("children[0].children[2]") and k == "started"]
    assert left_after[0] >= right_at_barrier[0]
    assert quiet_world.log[-2:] == [("left", quiet_world.log[-2][1]), ("left", quiet_world.log[-1][1])]


def test_sync_barrier_times_out_in_simulated_seconds():
    slow_partner = PLAN.replace("{duration: 0.12}", "{duration: 21.0}")  # past sync_barrier's 20 s
    t0 = time.monotonic()
    world, result, _ = run(slow_partner)
    assert time.monotonic() - t0 < 20.0  # simulated seconds, not wall seconds
    assert result.outcome == "failure" and result.failure is FailureKind.TIMEOUT
    left_sync = result.nodes["tree.children[0].children[0].children[1]"]
    assert left_sync.status == "failed" and "did not arrive within 20 s" in left_sync.reason


def test_a_partner_that_ends_without_arriving_fails_the_barrier_at_once():
    no_partner = PLAN.replace(
        """            - primitive: sync_barrier
              params: {name: meet}
            - primitive: wait
              params: {duration: 0.03}""",
        """            - primitive: wait
              params: {duration: 0.03}""",
    )
    world, result, _ = run(no_partner)
    assert result.outcome == "failure"
    left_sync = result.nodes["tree.children[0].children[0].children[1]"]
    assert left_sync.status == "failed" and "never arrived" in left_sync.reason
    assert world.sim_time_s < 0.5  # nobody waited for it in simulated time either
