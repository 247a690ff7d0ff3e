"""Step-through control from another thread: pause, step, resume, breakpoints, abort."""

import threading

import pytest

from spark_core.execution import EventBus, Executor, StepControl
from spark_core.grammar import parse_plan
from tests.doubles.kinematic_world import KinematicResolver, KinematicWorld
from tests.execution.test_executor import PICK_PLACE

WAIT_S = 10.0


class Harness:
    """Runs a plan on a worker thread and lets the test wait for specific events."""

    def __init__(self, control: StepControl):
        world = KinematicWorld({"cube": [0.5, 0.0, 0.02], "plate": [0.5, 0.2, 0.01]})
        self.bus = EventBus("step")
        self.control = control
        self.executor = Executor(world, KinematicResolver(world), bus=self.bus, control=control)
        self._cond = threading.Condition()
        self.bus.subscribe(self._on_event)
        self.result = None
        self.thread = threading.Thread(target=self._run, daemon=True)

    def _on_event(self, ev):
        with self._cond:
            self._cond.notify_all()

    def _run(self):
        self.result = self.executor.run(parse_plan(PICK_PLACE))

    def start(self):
        self.thread.start()
        return self

    def wait_paused(self, n: int):
        """Block until the n-th `paused` event has been published; returns its node path."""
        with self._cond:
            ok = self._cond.wait_for(lambda: len(self.paused()) >= n, timeout=WAIT_S)
        assert ok, f"no pause #{n}; events: {self.kinds()}"
        return self.paused()[n - 1].node_path

    def paused(self):
        return [e for e in self.bus.history if e.kind == "paused"]

    def kinds(self):
        return [(e.node_path, e.kind) for e in self.bus.history]

    def finish(self):
        self.thread.join(WAIT_S)
        assert not self.thread.is_alive()
        return self.result


def started(h):
    return [p for p, k in h.kinds() if k == "started" and p != "tree"]


def test_pause_step_resume():
    control = StepControl()
    control.pause()
    h = Harness(control).start()
    assert h.wait_paused(1) == "tree.children[0]" and started(h) == []
    assert control.state == "paused" and control.paused_at == "tree.children[0]"
    control.step()
    assert h.wait_paused(2) == "tree.children[1]"
    assert started(h) == ["tree.children[0]"]  # exactly one primitive ran
    control.step()
    assert h.wait_paused(3) == "tree.children[2]"
    assert started(h) == ["tree.children[0]", "tree.children[1]"]
    control.resume()
    result = h.finish()
    assert result.outcome == "success" and len(h.paused()) == 3


def test_breakpoint_pauses_before_the_node():
    control = StepControl(breakpoints=["tree.children[2]"])
    h = Harness(control).start()
    assert h.wait_paused(1) == "tree.children[2]"
    assert h.paused()[0].detail == {"reason": "breakpoint"}
    assert started(h) == ["tree.children[0]", "tree.children[1]"]
    control.remove_breakpoint("tree.children[2]")
    control.resume()
    assert h.finish().outcome == "success"


def test_abort_while_paused():
    control = StepControl(breakpoints=["tree.children[1]"])
    h = Harness(control).start()
    h.wait_paused(1)
    control.abort()
    result = h.finish()
    assert result.outcome == "aborted" and result.failed_node == "tree.children[1]"
    assert started(h) == ["tree.children[0]"]
    assert result.nodes["tree.children[3]"].status == "aborted"
    assert result.nodes["tree.children[0]"].status == "succeeded"


def test_abort_while_running_stops_at_the_next_primitive():
    control = StepControl()
    h = Harness(control)
    h.bus.subscribe(lambda e: e.node_path == "tree.children[1]" and e.kind == "succeeded" and control.abort())
    h.start()
    result = h.finish()
    assert result.outcome == "aborted"
    assert started(h) == ["tree.children[0]", "tree.children[1]"]


def test_pause_from_another_thread_mid_run():
    control = StepControl()
    h = Harness(control)
    h.bus.subscribe(lambda e: e.node_path == "tree.children[0]" and e.kind == "succeeded" and control.pause())
    h.start()
    assert h.wait_paused(1) == "tree.children[1]"
    control.resume()
    assert h.finish().outcome == "success"


@pytest.mark.parametrize("bad", ["tree.children[9]", "nope"])
def test_breakpoint_on_missing_path_never_triggers(bad):
    control = StepControl(breakpoints=[bad])
    assert Harness(control).start().finish().outcome == "success"
