"""The plan library kept in the trace store (table `plan_library`), same interface as the JSON-lines file."""

from __future__ import annotations

from ..perception.text_encoder import SHARED_ENCODER, TextEncoder
from ..planning.plan_library import PlanLibrary
from .store import TraceStore


class StorePlanLibrary(PlanLibrary):
    """Successful plans as rows of the trace store; every console and batch process sees the same library."""

    def __init__(self, store: TraceStore, enabled: bool = True, encoder: TextEncoder | None = None):
        self.store = store
        self.enabled = enabled
        self.encoder = encoder or SHARED_ENCODER

    def entries(self) -> list[dict]:
        return self.store.library_plans()

    def add(self, instruction: str, plan_yaml: str, scene_summary: str = "", trial_id: str | None = None) -> None:
        if self.enabled:
            self.store.add_library_plan(instruction, plan_yaml, scene_summary, trial_id)

    def import_jsonl(self, path) -> int:
        """Copy a JSON-lines library (the format before the store held it) into the store; returns rows added."""
        from pathlib import Path

        rows = PlanLibrary(Path(path)).entries()
        known = {(e["instruction"], e["plan"]) for e in self.entries()}
        added = 0
        for e in rows:
            if (e["instruction"], e["plan"]) not in known:
                self.store.add_library_plan(e["instruction"], e["plan"], e.get("scene_summary", ""))
                added += 1
        return added


__all__ = ["StorePlanLibrary"]
