"""Events carry the world's simulated time at publication (t_sim), on the bus and through a whole trial."""

from spark_core.execution import EventBus
from spark_core.trial import BaseSink, TrialConfig, run_trial


def test_the_bus_stamps_each_event_with_its_sim_clock_and_none_without_one():
    now = [0.0]
    bus = EventBus("t", sim_clock=lambda: now[0])
    a = bus.publish("tree", "started")
    now[0] = 1.25
    b = bus.publish("tree", "succeeded")
    assert (a.t_sim, b.t_sim) == (0.0, 1.25)
    assert b.to_dict()["t_sim"] == 1.25
    assert EventBus("u").publish("tree", "started").t_sim is None


class WorldClock(BaseSink):
    """Reads the world's simulated time when each event arrives (callbacks run inside publish)."""

    def __init__(self):
        self.world = None
        self.seen: list[tuple[float | None, float]] = []

    def on_start(self, ctx):
        self.world = ctx.world

    def on_event(self, event):
        self.seen.append((event.t_sim, self.world.sim_time_s))


def test_a_trials_events_carry_increasing_sim_time_equal_to_the_worlds():
    clock = WorldClock()
    out = run_trial(TrialConfig("lift_block", segmenter="sim"), [clock])
    assert out.success and len(clock.seen) >= 4
    for t_sim, world_t in clock.seen:
        assert t_sim is not None and abs(t_sim - world_t) < 1e-6
    times = [t for t, _ in clock.seen]
    assert times == sorted(times) and times[-1] > times[0]  # primitives take simulated time between events
    assert times[-1] <= out.sim_time_s + 1e-6
    assert [e.t_sim for e in out.result.events] == times
