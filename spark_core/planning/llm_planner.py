"""The part of an LLM planner that does not depend on the vendor: the BT call, the prompt-synthesis call and the
variant call, all through the vendor's one `_call`; each backend supplies only its SDK call and its errors."""

from __future__ import annotations

from .llm import CallOutcome, LLMSettings, Synthesis, Turn, plan_with_llm, synthesise_with_llm, variants_with_llm
from .protocol import PlanRequest, PlanResult


class LLMPlanner:
    """Base of the `gemini` and `openai` planners. Subclasses set `name`, `settings` and `calls` in their
    constructor and implement `_call` (one request; TransientError / PlannerUnavailable on failure)."""

    name: str
    settings: LLMSettings
    calls: list[dict]  # the prompt-synthesis and variant calls made, as the trace keeps them

    def plan(self, request: PlanRequest) -> PlanResult:
        return plan_with_llm(self.name, self.settings, request, self._call)

    def prompt_variants(self, labels: list[str], k: int = 3) -> dict[str, list[str]]:
        """The variant call: k alternative text prompts per object label (colour, shape, material)."""
        return variants_with_llm(self.settings, labels, k, self._call, self.calls.append)

    def synthesise(self, instruction: str, image_png: bytes | None, k: int = 3) -> Synthesis:
        """The paper's prompt-synthesis call: the objects to detect (and k alternative prompts each when k > 0)
        from the task language and the agentview image; recorded in `calls`."""
        return synthesise_with_llm(self.settings, instruction, image_png, k, self._call, self.calls.append)

    def _call(
        self,
        system: str,
        turns: list[Turn],
        image: bytes | None,
        schema: dict | None = None,
        max_output_tokens: int | None = None,
    ) -> CallOutcome:
        raise NotImplementedError
