"""An abort accepted while a primitive runs stops it within a control period, and a trial the operator aborted
never ends as a success (adversarial review M1)."""

from __future__ import annotations

from spark_core.execution import EventBus, Executor, StepControl
from spark_core.grammar import parse_plan
from spark_core.trial import BaseSink, TrialConfig, Verdict, run_trial
from tests.doubles.kinematic_world import KinematicResolver, KinematicWorld
from tests.execution.test_executor import PICK_PLACE

LONG_WAIT = """task: wait, then nudge the hand up
tree:
  type: sequence
  children:
    - primitive: wait
      params: {duration: 5.0}
    - primitive: move_relative
      params: {dz: 0.05}
"""


class AbortWhenStarted(BaseSink):
    def __init__(self, control: StepControl, node_path: str):
        self.control, self.node_path = control, node_path

    def on_event(self, event) -> None:
        if event.node_path == self.node_path and event.kind == "started":
            self.control.abort()


def test_an_abort_during_the_last_primitive_is_never_a_success():
    world = KinematicWorld({"cube": [0.5, 0.0, 0.02], "plate": [0.5, 0.2, 0.01]})
    control, bus = StepControl(), EventBus("abort-last")
    last = "tree.children[3]"
    bus.subscribe(lambda e: e.node_path == last and e.kind == "started" and control.abort())
    result = Executor(world, KinematicResolver(world), bus=bus, control=control).run(parse_plan(PICK_PLACE))
    assert result.outcome == "aborted" and result.failed_node == last


def test_an_abort_interrupts_the_running_primitive_of_a_simulated_trial():
    control = StepControl()
    config = TrialConfig("lift_block", segmenter="privileged-keypoints", plan_text=LONG_WAIT, recovery=False)
    out = run_trial(config, sinks=[AbortWhenStarted(control, "tree.children[0]")], control=control)
    assert out.verdict is Verdict.ABORTED and out.failed_node == "tree.children[0]"
    # setup and the final settle take < 1 s; the wait alone would take 5 s
    assert out.sim_time_s < 2.0, f"the 5 s wait ran on for {out.sim_time_s:.2f} s of simulated time after the abort"
