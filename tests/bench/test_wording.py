"""The wording corpus and `spark bench wording`'s planning check: the split is the documented fixed rule, and the
check tells a plan with the official plan's effect from one that carries the wrong thing or refuses."""

import hashlib
import re

import numpy as np
import pytest

from spark_core.bench import wording
from spark_core.perception import Keypoint
from spark_core.planning import SceneView


def test_the_corpus_is_large_enough_split_by_its_hash_rule_and_names_real_tasks():
    dev, test = wording.load("dev"), wording.load("test")
    # dev: the original 351 (hash split; the odd-hash half is the retired first test half), then later probes (.pN,
    # .qN, .sN, .kN, .mN) and the retired second to sixth test halves (.rN, .tN, .vN, .xN, .zN); test: the seventh
    # half (.yN), written apart
    later = [e for e in dev if re.search(r"\.[pqsrtvxzkm][0-9]+$", e["id"])]
    first = [e for e in dev if e not in later]
    assert later and len(first) >= 300
    odd = [hashlib.sha256(f"{e['task']}|{e['instruction']}".encode()).digest()[0] % 2 for e in first]
    assert 0.4 < sum(odd) / len(first) < 0.6  # the retired first test half is in dev, next to the first dev half
    assert len(test) >= 180 and all(re.search(r"\.y[0-9]+$", e["id"]) for e in test)
    assert not any(re.search(r"\.y[0-9]+$", e["id"]) for e in dev)
    seen = {e["instruction"].lower().strip() for e in dev}
    assert not [e["id"] for e in test if e["instruction"].lower().strip() in seen]  # fresh wording, not reused
    for e in dev + test:
        assert e["expect"] == "goal" or e["expect"] == f"refuse:{e['style']}"
    assert len({e["id"] for e in dev + test}) == len(dev) + len(test)
    styles = {"goal_state", "trailing", "source_dest", "located", "ordinal", "possessive", "synonym", "negation"}
    styles |= {"polite", "pronoun", "multistep", "nonsense", "absent", "ambiguous"}
    assert {e["style"] for e in dev} >= styles and {e["style"] for e in test} == styles
    assert {e["suite"] for e in test} == {"builtin", "capbench", "liberopro"}
    cells = {e["task"].split(":")[0] for e in test if e["suite"] == "liberopro"}
    assert cells == {f"libero_{s}_{v}" for s in ("spatial", "object", "goal") for v in ("swap", "task")}
    assert 0.6 < sum(e["expect"] == "goal" for e in test) / len(test) < 0.9
    for task in wording.EXEC_TASKS:  # the execution sample has its full share in the test half
        assert sum(e["task"] == task and e["expect"] == "goal" for e in test) >= wording.EXEC_PER_TASK, task
    with pytest.raises(ValueError, match="unknown corpus half"):
        wording.load("train")


def _view(**where):
    return SceneView({k.replace("_", " "): Keypoint(k, np.array(v, float), np.full(3, 0.04)) for k, v in where.items()})


def _plan(*leaves):
    return {"tree": {"type": "sequence", "children": [{"type": t, "params": p} for t, p in leaves]}}


def test_a_stack_has_the_effect_of_a_pick_and_place_on_the_same_things():
    view = _view(red=(0.5, 0, 0.02), blue=(0.5, 0.2, 0.02), crimson=(0.5, 0.001, 0.02), navy=(0.5, 0.2, 0.02))
    stack = wording.signature(_plan(("stack", {"keypoint_label": "red", "target_label": "blue"})), view)
    carry = wording.signature(
        _plan(("pick", {"keypoint_label": "crimson"}), ("place", {"target_label": "navy"}), ("go_home", {})), view
    )
    assert wording.same_effect(stack, carry)
    wrong = wording.signature(_plan(("pick", {"keypoint_label": "blue"}), ("place", {"target_label": "red"})), view)
    assert not wording.same_effect(stack, wrong)
    turned_off = wording.signature(_plan(("turn_knob", {"keypoint_label": "red", "angle": -90.0})), view)
    turned_on = wording.signature(_plan(("turn_knob", {"keypoint_label": "red", "angle": 90.0})), view)
    assert not wording.same_effect(turned_on, turned_off)


def test_moves_that_share_no_place_may_come_in_another_order_but_dependent_ones_may_not():
    view = _view(red=(0.5, 0, 0.02), blue=(0.5, 0.2, 0.02), green=(0.3, 0.1, 0.02), plate=(0.6, -0.2, 0.01))
    basket = Keypoint("basket", np.array([0.4, -0.3, 0.05]), np.full(3, 0.1))
    view.keypoints["basket"] = basket

    def sig(*moves, into=False):
        leaves = []
        for thing, where in moves:
            leaves.append(("pick", {"keypoint_label": thing}))
            leaves.append(("place_in", {"container_label": where}) if into else ("place", {"target_label": where}))
        return wording.signature(_plan(*leaves), view)

    # two things to two places: either order reaches the goal
    assert wording.same_effect(sig(("red", "plate"), ("blue", "green")), sig(("blue", "green"), ("red", "plate")))
    # two things into one container: either order
    assert wording.same_effect(
        sig(("red", "basket"), ("blue", "basket"), into=True), sig(("blue", "basket"), ("red", "basket"), into=True)
    )
    # two things on top of one place: the second lands on the first, so the order is part of the goal
    assert not wording.same_effect(sig(("red", "plate"), ("blue", "plate")), sig(("blue", "plate"), ("red", "plate")))
    # a tower: the red block on the blue one, then the green one on the red one; not the other way round
    assert not wording.same_effect(sig(("green", "red"), ("red", "blue")), sig(("red", "blue"), ("green", "red")))
    # a thing moved, then the thing it was moved onto moved: dependent
    assert not wording.same_effect(sig(("blue", "plate"), ("red", "blue")), sig(("red", "blue"), ("blue", "plate")))
    # another order is still the same steps: a missing or different move is wrong
    assert not wording.same_effect(sig(("blue", "green")), sig(("red", "plate"), ("blue", "green")))
    assert not wording.same_effect(sig(("blue", "plate"), ("red", "green")), sig(("red", "plate"), ("blue", "green")))
    knob = wording.signature(_plan(("turn_knob", {"keypoint_label": "green", "angle": 90.0})), view)
    moved = sig(("red", "plate"))
    assert not wording.same_effect(moved + knob, knob + moved)  # a fixture's step keeps its place in the order


def test_planning_check_on_a_real_scene_tells_right_from_wrong_and_refusals():
    entries = [
        {"id": "a", "style": "synonym", "suite": "builtin", "task": "block_on_plate", "expect": "goal"},
        {"id": "b", "style": "goal_state", "suite": "builtin", "task": "block_on_plate", "expect": "goal"},
        {"id": "c", "style": "absent", "suite": "builtin", "task": "block_on_plate", "expect": "refuse:absent"},
    ]
    texts = ["set the crimson cube down on the dish", "the plate belongs on the red block", "put the giraffe on it"]
    rows = wording.plan_entries([dict(e, instruction=t, half="dev") for e, t in zip(entries, texts)])
    assert [r["correct"] for r in rows] == [True, False, True]
    assert rows[2]["planned"] is False and "giraffe" in rows[2]["error"]
    s = wording.summary(rows)
    assert s["planning_success"] == 0.5 and s["nonsense_absent_refused"] == 1.0


def test_execution_is_compared_with_the_official_wording_of_the_same_tasks_per_half():
    def row(task, half, ok):
        return {"task": task, "half": half, "success": ok, "wording": "official" if half == "official" else "x"}

    rows = [row("a", "official", True), row("a", "official", True), row("b", "official", False)]
    rows += [row("a", "dev", True), row("a", "dev", False), row("b", "test", False), row("b", "test", True)]
    dev, test = wording.exec_summary(rows, "dev"), wording.exec_summary(rows, "test")
    assert (dev["reworded"], dev["official"], dev["ratio"]) == (0.5, 1.0, 0.5)
    assert (test["reworded"], test["official"], test["ratio"]) == (0.5, 0.0, 0.0)  # nothing to compare with


def _top(label, xyz, size, cells):
    """A keypoint with a seen top face over the given 1 cm cells (x, y in m, cell centres)."""
    return Keypoint(label, np.array(xyz, float), np.array(size, float), detail={"footprint_xy_m": cells})


def test_two_place_targets_with_the_same_support_are_the_same_destination():
    # a cabinet (top at 0.23 m) and its top drawer's front, whose point lies inside the cabinet's top face, lower
    cabinet_cells = [[x / 100 + 0.005, y / 100 + 0.005] for x in range(28, 52) for y in range(-37, -17)]
    view = SceneView(
        {
            "bowl": Keypoint("bowl", np.array([0.6, 0.13, 0.03]), np.full(3, 0.05)),
            "cabinet": _top("cabinet", (0.40, -0.27, 0.18), (0.24, 0.18, 0.10), cabinet_cells),
            "drawer top": _top("drawer top", (0.40, -0.177, 0.187), (0.2, 0.0, 0.06), [[0.405, -0.175]]),
            "plate": _top("plate", (0.6, -0.1, 0.01), (0.12, 0.12, 0.01), [[0.605, -0.095]]),
        }
    )

    def carry(target, into=False):
        put = ("place_in", {"container_label": target}) if into else ("place", {"target_label": target})
        return wording.signature(_plan(("pick", {"keypoint_label": "bowl"}), put), view)

    assert wording.same_effect(carry("drawer top"), carry("cabinet"))
    assert wording.same_effect(carry("cabinet"), carry("drawer top"))
    assert not wording.same_effect(carry("drawer top", into=True), carry("cabinet"))  # into a drawer is not on top
    assert not wording.same_effect(carry("plate"), carry("cabinet"))


def test_plan_only_skips_the_execution_sample(monkeypatch, tmp_path):
    import argparse
    import json

    from spark_cli import bench as cli

    entry = {"id": "a", "style": "synonym", "suite": "builtin", "task": "block_on_plate", "expect": "goal"}
    row = dict(entry, half="dev", instruction="x", planned=True, correct=True, error="", understood=[])
    ran: list[str] = []
    monkeypatch.setattr(wording, "load", lambda half: [dict(entry, half=half)])
    monkeypatch.setattr(wording, "plan_entries", lambda entries, seed, progress, **k: ran.append("plan") or [row])
    monkeypatch.setattr(wording, "execute_sample", lambda *a, **k: ran.append("execute") or [])
    out = tmp_path / "rows.json"
    args = argparse.Namespace(half="dev", seed=0, trials=None, json=str(out), plan_only=True)
    text = cli._wording(args, "spark bench wording --half dev --plan-only")
    assert ran == ["plan"] and json.loads(out.read_text())["execution"] == []
    assert "execution success" not in text
    # its protocol describes no trials it did not run
    assert "execution: not run (plan-only)" in text and "real trials" not in text
    cli._wording(argparse.Namespace(**{**vars(args), "plan_only": False}), "spark bench wording --half dev")
    assert ran == ["plan", "plan", "execute"]


def test_corpus_option_plans_a_file_of_the_dev_schema_instead_of_the_halves(monkeypatch, tmp_path):
    import argparse

    import yaml

    from spark_cli import bench as cli

    entry = {"id": "p.1", "style": "synonym", "suite": "builtin", "task": "block_on_plate", "expect": "goal"}
    probe = tmp_path / "probe.yaml"
    probe.write_text(yaml.safe_dump([dict(entry, instruction="x")]))
    seen: list[list[dict]] = []
    monkeypatch.setattr(wording, "load", lambda half: pytest.fail("--corpus must not load a half"))
    monkeypatch.setattr(
        wording,
        "plan_entries",
        lambda entries, seed, progress, **k: (
            seen.append(entries) or [dict(e, planned=True, correct=True, error="", understood=[]) for e in entries]
        ),
    )
    args = argparse.Namespace(half=None, seed=0, trials=None, json=None, plan_only=True, corpus=str(probe))
    text = cli._wording(args, "spark bench wording --corpus probe.yaml --plan-only")
    assert [e["id"] for e in seen[0]] == ["p.1"] and seen[0][0]["half"] == "dev"
    assert "| synonym | 1 | 100" in text
    bad = tmp_path / "bad.yaml"
    bad.write_text(yaml.safe_dump([dict(entry, task="no_such_task", instruction="x")]))
    with pytest.raises(ValueError, match="no_such_task"):
        wording.load_file(bad)


def test_progress_lines_name_the_entry_but_never_its_wording_or_the_planner_message():
    from spark_cli import bench as cli

    row = {
        "id": "builtin.x.v7",
        "style": "negation",
        "expect": "goal",
        "half": "dev",
        "instruction": "zebra pick",
        "planned": False,
        "correct": False,
        "error": "could not place 'zebra'",
        "understood": ["zebra pick"],
    }
    line = cli._wording_line(row)
    assert "builtin.x.v7" in line and "negation" in line and "refused" in line and "FAIL" in line
    assert "zebra" not in line
    assert "planned" in cli._wording_line(dict(row, planned=True, correct=True))


def test_a_blind_run_prints_counts_and_figures_but_no_entry_id_style_or_failure_list(monkeypatch, capsys, tmp_path):
    """`--blind` keeps a probe or the test half unseen: the person running it learns the aggregates alone."""
    import argparse

    import yaml

    from spark_cli import bench as cli

    entries = [
        {"id": "secret.one", "style": "zzstyle", "suite": "builtin", "task": "block_on_plate", "expect": "goal"},
        {"id": "secret.two", "style": "zzstyle", "suite": "builtin", "task": "block_on_plate", "expect": "goal"},
    ]
    probe = tmp_path / "probe.yaml"
    probe.write_text(yaml.safe_dump([dict(e, instruction="put the block on the plate") for e in entries]))

    def plan_entries(entries, seed, progress, **k):
        rows = [dict(e, planned=i == 0, correct=i == 0, error="no", understood=[]) for i, e in enumerate(entries)]
        for r in rows:
            progress(r)
        return rows

    monkeypatch.setattr(wording, "plan_entries", plan_entries)
    args = argparse.Namespace(half=None, seed=0, trials=None, json=None, plan_only=True, corpus=str(probe))
    seen = cli._wording(args, "spark bench wording --corpus probe.yaml --plan-only")
    seen_out = capsys.readouterr().out
    assert "secret.one" in seen_out and "secret.two" in seen  # without --blind: ids in progress and failure list
    blind = cli._wording(argparse.Namespace(**vars(args), blind=True), "spark bench wording --blind")
    out = capsys.readouterr().out + blind
    assert "secret" not in out and "[2/2] planned" in out
    assert "50.0 %" in blind  # the aggregate planning figure is still reported
    assert "zzstyle" in blind  # per-style rows are aggregates (counts), kept


def test_every_probe_file_loads_and_a_refusal_says_why(tmp_path):
    import yaml

    files = sorted(wording.CORPUS_DIR.glob("probe*.yaml"))
    assert len(files) >= 9
    for path in files:
        entries = wording.load_file(path)
        assert all(e["expect"] == "goal" or e["expect"] == f"refuse:{e['style']}" for e in entries), path.name
    bad = tmp_path / "probe.yaml"
    row = {"id": "a", "style": "absent", "suite": "builtin", "task": "block_on_plate", "expect": "refuse"}
    bad.write_text(yaml.safe_dump([dict(row, instruction="put the banana on the plate")]))
    with pytest.raises(ValueError, match="probe.yaml a: expect 'refuse' is neither 'goal' nor one of refuse:absent"):
        wording.load_file(bad)


def test_json_never_holds_a_test_half_entry_nor_any_entry_of_a_blind_run(monkeypatch, capsys, tmp_path):
    """The frozen test half is looked at only in aggregate: `--json` (the full table's run writes one) keeps its rows
    out of the file and writes their summary; a `--blind` run writes no entry at all."""
    import argparse
    import json

    from spark_cli import bench as cli

    def entry(i: str, half: str) -> dict:
        return {
            "id": f"{half}.{i}",
            "style": "synonym",
            "suite": "builtin",
            "task": "block_on_plate",
            "expect": "goal",
            "half": half,
            "instruction": f"secret words {half} {i}",
        }

    monkeypatch.setattr(wording, "load", lambda half: [entry("1", half), entry("2", half)])

    def plan_entries(entries, seed, progress, **k):
        rows = [dict(e, planned=e["id"].endswith("1"), correct=e["id"].endswith("1"), error="") for e in entries]
        for r in rows:
            progress(dict(r, understood=[]))
        return [dict(r, understood=[]) for r in rows]

    monkeypatch.setattr(wording, "plan_entries", plan_entries)
    out = tmp_path / "rows.json"
    args = argparse.Namespace(half=None, seed=0, trials=None, json=str(out), plan_only=True)
    cli._wording(args, "spark bench wording --plan-only")
    progress = capsys.readouterr().out
    assert "dev.2" in progress and "test." not in progress  # test-half progress lines are counts alone
    data = json.loads(out.read_text())
    assert [r["id"] for r in data["planning"]] == ["dev.1", "dev.2"]
    assert "secret words test" not in out.read_text()
    assert data["withheld"]["planning_entries"] == 2
    assert data["withheld"]["planning"]["planning_success"] == 0.5
    cli._wording(argparse.Namespace(**vars(args), blind=True), "spark bench wording --blind --plan-only")
    data = json.loads(out.read_text())
    assert data["planning"] == [] and "secret" not in out.read_text()
    assert data["withheld"]["planning_entries"] == 4


def test_failures_are_counted_by_kind_from_the_messages_opening_words_never_quoted():
    goal = {"expect": "goal", "correct": False, "style": "synonym", "half": "dev", "planned": False}
    rows = [
        dict(goal, error="could not find 'zebra mug' in the scene: ..."),
        dict(goal, error="'take the bowl': which bowl? (understood: ...)"),
        dict(goal, error="no action I know in 'zebra'; I understand verbs such as ..."),
        dict(goal, error="the instruction also asks for the opposite of what it asks: 'x' ..."),
        dict(goal, error="lifting 'zebra' with both arms needs a second handle"),
        dict(goal, planned=True, error=""),
        dict(goal, correct=True, planned=True, error=""),
    ]
    kinds = [wording.failure_kind(r) for r in rows[:6]]
    assert kinds == [k for k, _ in wording.FAILURE_KINDS] + [
        "refused: other reason",
        "planned, not the official plan's effect",
    ]
    text = wording.section([dict(r, id=f"e{i}") for i, r in enumerate(rows)], [], "cmd", 1)
    assert "| refused: a phrase perception did not find | 1 | - |" in text
    assert "| planned, not the official plan's effect | 1 | - |" in text
    assert "zebra" not in text
