"""The plan library: stored after success, retrieved by instruction similarity, can be turned off."""

from spark_core.planning.library import PlanLibrary
from spark_core.planning.prompt import user_prompt
from spark_core.planning import PlanRequest


def test_store_and_retrieve_by_similarity(tmp_path):
    lib = PlanLibrary(tmp_path / "plans.jsonl")
    lib.add("put the red block on the plate", "task: a\ntree: {primitive: wait}\n", "- red block ...")
    lib.add("open the drawer", "task: b\ntree: {primitive: wait}\n")
    lib.add("turn on the stove", "task: c\ntree: {primitive: wait}\n")
    again = PlanLibrary(tmp_path / "plans.jsonl")  # persisted
    (best, plan), = again.examples("place the crimson cube onto the dish", k=1)
    assert best == "put the red block on the plate" and plan.startswith("task: a")
    assert [i for i, _ in again.examples("switch the cooktop on", k=2)][0] == "turn on the stove"
    prompt = user_prompt(PlanRequest("place the cube on the dish", examples=again.examples("place the cube on the dish", k=1)))
    assert prompt.startswith("Example task: put the red block on the plate")


def test_disabled_library_stores_nothing(tmp_path):
    lib = PlanLibrary(tmp_path / "plans.jsonl", enabled=False)
    lib.add("x", "task: x\ntree: {primitive: wait}\n")
    assert lib.examples("x") == () and not (tmp_path / "plans.jsonl").exists()
