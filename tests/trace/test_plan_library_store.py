"""The plan library lives in the trace store: rows survive reopening, examples come back by similarity, and the
old JSON-lines file imports once without duplicates."""

from spark_core.planning.plan_library import PlanLibrary
from spark_core.trace import TraceStore
from spark_core.trace.library_table import StorePlanLibrary


def test_store_library_keeps_plans_and_retrieves_similar_ones(store_url):
    url = store_url
    lib = StorePlanLibrary(TraceStore(url))
    lib.add(
        "stack the red block on the blue block", "task: stack\ntree: {primitive: wait}\n", "2 blocks", trial_id="t-1"
    )
    lib.add("open the drawer", "task: drawer\ntree: {primitive: wait}\n")
    again = StorePlanLibrary(TraceStore(url))  # another process opening the same store
    assert [e["instruction"] for e in again.entries()] == ["stack the red block on the blue block", "open the drawer"]
    assert again.entries()[0]["trial_id"] == "t-1"
    best = again.examples("put the red cube on top of the blue cube", k=1)
    assert best[0][0] == "stack the red block on the blue block"
    off = StorePlanLibrary(TraceStore(url), enabled=False)
    off.add("ignored", "x")
    assert off.examples("open the drawer") == () and len(again.entries()) == 2


def test_jsonl_library_imports_once(tmp_path):
    old = PlanLibrary(tmp_path / "plans.jsonl")
    old.add("open the drawer", "task: a\ntree: {primitive: wait}\n")
    old.add("pick up the mug", "task: b\ntree: {primitive: wait}\n")
    lib = StorePlanLibrary(TraceStore(f"sqlite:///{tmp_path / 'lib.db'}"))
    assert lib.import_jsonl(tmp_path / "plans.jsonl") == 2
    assert lib.import_jsonl(tmp_path / "plans.jsonl") == 0
    assert sorted(e["instruction"] for e in lib.entries()) == ["open the drawer", "pick up the mug"]
