"""Planning: one planner call from (instruction, what perception saw) to a typed behavior tree."""

from .protocol import Planner, PlanRequest, PlanResult, SceneView, Usage

__all__ = ["PlanRequest", "PlanResult", "Planner", "SceneView", "Usage"]
