"""The plan library: stored after success, retrieved by instruction similarity, can be turned off."""

from spark_core.planning import PlanRequest
from spark_core.planning.plan_library import PlanLibrary
from spark_core.planning.prompt import user_prompt


def test_store_and_retrieve_by_similarity(tmp_path):
    lib = PlanLibrary(tmp_path / "plans.jsonl")
    lib.add("put the red block on the plate", "task: a\ntree: {primitive: wait}\n", "- red block ...")
    lib.add("open the drawer", "task: b\ntree: {primitive: wait}\n")
    lib.add("turn on the stove", "task: c\ntree: {primitive: wait}\n")
    again = PlanLibrary(tmp_path / "plans.jsonl")  # persisted
    ((best, plan),) = again.examples("place the crimson cube onto the dish", k=1)
    assert best == "put the red block on the plate" and plan.startswith("task: a")
    assert [i for i, _ in again.examples("switch the cooktop on", k=2)][0] == "turn on the stove"
    prompt = user_prompt(
        PlanRequest("place the cube on the dish", examples=again.examples("place the cube on the dish", k=1))
    )
    assert prompt.startswith("Example task: put the red block on the plate")


def test_disabled_library_stores_nothing(tmp_path):
    lib = PlanLibrary(tmp_path / "plans.jsonl", enabled=False)
    lib.add("x", "task: x\ntree: {primitive: wait}\n")
    assert lib.examples("x") == () and not (tmp_path / "plans.jsonl").exists()


def test_config_file_selects_backends_and_prices(tmp_path, monkeypatch):
    import pytest

    from spark_core.config import load_config

    (tmp_path / "spark.yaml").write_text(
        "planner: openai\nmodel: qwen\nbase_url: http://127.0.0.1:9/v1\nprices: {qwen: [0.1, 0.4]}\n"
    )
    monkeypatch.chdir(tmp_path)
    cfg = load_config()
    assert (cfg.planner, cfg.model, cfg.prices["qwen"]) == ("openai", "qwen", (0.1, 0.4))
    (tmp_path / "bad.yaml").write_text("planer: rules\n")
    with pytest.raises(ValueError, match="unknown setting\\(s\\) planer"):
        load_config(tmp_path / "bad.yaml")
    (tmp_path / "bad2.yaml").write_text("prices: {m: cheap}\n")
    with pytest.raises(ValueError, match="prices.m: expected"):
        load_config(tmp_path / "bad2.yaml")


def test_cli_takes_the_planner_from_the_config(tmp_path, monkeypatch, capsys):
    from spark_cli import main

    (tmp_path / "spark.yaml").write_text("planner: openai\n")
    monkeypatch.chdir(tmp_path)
    code = main(["plan", "put the red block on the plate", "--task", "block_on_plate"])
    assert code == 2 and "planner 'openai' unavailable: the openai planner needs --model" in capsys.readouterr().err
