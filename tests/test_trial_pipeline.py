"""One trial pipeline: the console's worker, `spark run`, the local pool and Ray run the same TrialConfig through
`spark_core.trial.run_trial` and agree on the verdict, the events and the trajectory; success needs the task's
predicate AND the tree; the verdicts say which part failed."""

from __future__ import annotations

import time

import pytest
from fastapi.testclient import TestClient

from spark_core.catalog import SEGMENTERS
from spark_core.trace import TraceStore
from spark_core.trial import TrialConfig, TrialConfigError, Verdict, run_trial

UNICORN = """task: lift the red block, then go to the unicorn
tree:
  type: sequence
  children:
    - primitive: pick
      params: {keypoint_label: red block}
    - primitive: move_to_keypoint
      params: {keypoint_label: unicorn, offset_z: 0.1}
"""

NUDGE = """task: nudge the hand up
tree:
  type: sequence
  children:
    - primitive: move_relative
      params: {dz: 0.05}
"""


def _fingerprint(trial: dict) -> tuple:
    """What must agree between callers: verdict, every (node, event kind) in order, the trajectory's length."""
    return (trial["verdict"], [(e["node_path"], e["kind"]) for e in trial["events"]], len(trial["trajectory"]))


def test_one_config_gives_the_same_verdict_events_and_trajectory_through_all_four_callers(tmp_path):
    from server.app import create_app
    from server.settings import Settings
    from spark_cli import main
    from spark_core.bench import reference_suite

    config = TrialConfig("lift_block", segmenter="sim", seed=2)
    seen = {}

    url = f"sqlite:///{tmp_path / 'console.db'}"  # 1. the console's worker process
    with TestClient(
        create_app(Settings(store_url=url, workers=1, viser=False, artifacts_dir=str(tmp_path / "art")))
    ) as c:
        tid = c.post("/api/trials", json={"task": "lift_block", "segmenter": "sim", "seed": 2}).json()["id"]
        t0 = time.monotonic()
        while c.get(f"/api/trials/{tid}").json()["status"] not in ("done", "interrupted"):
            assert time.monotonic() - t0 < 120, "console trial did not finish"
            time.sleep(0.1)
    seen["console"] = TraceStore(url).get_trial(tid)

    url = f"sqlite:///{tmp_path / 'cli.db'}"  # 2. spark run
    assert main(["run", "lift_block", "--segmenter", "sim", "--seed", "2", "--store", url]) == 0
    store = TraceStore(url)
    seen["cli"] = store.get_trial(store.trial_ids()[0])

    for executor in ("local", "ray"):  # 3. and 4. spark bench's local pool, and Ray
        url = f"sqlite:///{tmp_path / f'{executor}.db'}"
        (row,) = reference_suite.run(
            ["lift_block"], 1, seed=2, workers=2, template=config, executor=executor, store_url=url
        )
        store = TraceStore(url)
        seen[executor] = store.get_trial(store.trial_ids()[0])
        assert row["verdict"] == seen[executor]["verdict"] and row["trajectory_len"] == len(
            seen[executor]["trajectory"]
        )

    prints = {caller: _fingerprint(t) for caller, t in seen.items()}
    assert prints["console"][0] == "success" and len(prints["console"][1]) >= 4 and prints["console"][2] > 100
    assert all(p == prints["console"] for p in prints.values()), {k: (p[0], len(p[1]), p[2]) for k, p in prints.items()}
    assert {t["segmenter"] for t in seen.values()} == {"sim"}


def test_a_failed_tree_is_not_a_success_even_when_the_predicate_holds(tmp_path, capsys):
    """The plan lifts the block (predicate true) and then cannot find a unicorn: the tree failed."""
    out = run_trial(TrialConfig("lift_block", plan_text=UNICORN, segmenter="sim"))
    assert out.verdict is Verdict.TREE_FAILED and not out.success
    assert out.tree_status == "failure" and out.failure == "perception" and out.failed_node == "tree.children[1]"
    assert "unicorn" in out.reason

    from spark_cli import main

    plan = tmp_path / "unicorn.yaml"
    plan.write_text(UNICORN)
    assert main(["run", "lift_block", "--plan", str(plan), "--no-store"]) == 1
    text = capsys.readouterr().out
    assert "verdict: tree_failed" in text and "behavior tree: failure" in text


def test_every_node_passing_with_the_goal_unmet_names_the_unmet_condition():
    out = run_trial(TrialConfig("lift_block", plan_text=NUDGE, segmenter="privileged-keypoints"))
    assert out.verdict is Verdict.TASK_UNMET and out.tree_status == "success" and out.task_success is False
    assert out.unmet == "red block bottom > 5 cm above the table and held" and out.unmet in out.reason


def test_a_planner_that_writes_no_plan_is_a_planner_error_with_what_it_said():
    out = run_trial(TrialConfig("lift_block", "sing the anthem loudly", planner="rules", segmenter="sim"))
    assert out.verdict is Verdict.PLANNER_ERROR and out.tree_status is None and out.events == 0
    assert out.reason.startswith("no plan:") and out.failure == "planner"


def test_an_abort_before_start_and_a_crash_are_verdicts_not_exceptions(monkeypatch):
    from spark_core.execution import StepControl

    control = StepControl()
    control.abort()
    out = run_trial(TrialConfig("lift_block", segmenter="privileged-keypoints"), control=control)
    assert out.verdict is Verdict.ABORTED and out.reason == "cancelled before it started"

    from spark_core.execution import Executor

    def boom(self, plan):
        raise RuntimeError("simulated fault")

    monkeypatch.setattr(Executor, "run", boom)
    out = run_trial(TrialConfig("lift_block", segmenter="privileged-keypoints"))
    assert out.verdict is Verdict.CRASHED and "RuntimeError: simulated fault" in out.reason
    assert "traceback" in out.protocol


@pytest.mark.parametrize(
    "changes,message",
    [
        ({"task": "unicorn_dance"}, "unknown task 'unicorn_dance'"),
        (
            {"segmenter": "privileged"},
            f"unknown segmenter 'privileged'; available: {', '.join(SEGMENTERS)}",
        ),
        ({"planner": "openai"}, "model: the openai planner needs a model name"),
        ({"task": "lift_tray", "embodiment": "panda"}, "embodiment: task 'lift_tray' runs on bimanual, not 'panda'"),
        ({"plan_text": "task: t\ntree: {primitive: grasp, params: {force: high}}"}, "plan_text: tree.params.force"),
        ({"time_limit_s": -1.0}, "time_limit_s: expected (0, 3600]"),
    ],
)
def test_a_bad_config_is_refused_before_anything_runs_naming_the_field(changes, message):
    from dataclasses import replace

    with pytest.raises(TrialConfigError, match=message.replace("(", r"\(").replace(")", r"\)").replace("[", r"\[")):
        replace(TrialConfig("lift_block"), **changes).check()


def test_pacing_holds_simulated_time_to_the_wall_clock():
    """At 0.5x real time a plan's simulated seconds take at least twice as many wall seconds."""
    out = run_trial(TrialConfig("lift_block", plan_text=NUDGE, segmenter="privileged-keypoints", pacing=0.5))
    events = out.result.events
    wall_s = events[-1].t - events[0].t
    assert out.result.sim_time_s > 0.2 and wall_s >= 0.9 * out.result.sim_time_s / 0.5
