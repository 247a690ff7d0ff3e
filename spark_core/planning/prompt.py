"""Planner prompts, generated from the grammar registry (never a hand-written primitive list)."""

from __future__ import annotations

from ..grammar import REGISTRY, Registry, plan_json_schema
from ..grammar.reference import signature
from ..grammar.spec import Tier
from .protocol import PlanRequest

GUIDANCE = """\
Spatial reasoning:
- World frame: x points away from the robot, y to the robot's left, z up; metres and radians.
- Name objects only by the labels perception reported; every label is resolved to a live 3D keypoint when the
  step runs, so never write coordinates for objects.
- Grasp before you lift, carry or pour; release (or place) before grasping something else.
- Containers (bowls, baskets, drawers, trays): use place_in. Surfaces and objects to stack on: place or stack.
- Use parallel with one arm-tagged branch per arm only when the robot has two arms.
"""


def grammar_listing(registry: Registry = REGISTRY) -> str:
    lines = []
    for tier in Tier:
        lines.append(f"{tier.value} primitives:")
        for spec in registry.by_tier(tier):
            units = ", ".join(f"{s.name} in {s.unit}" for s in spec.slots if s.unit)
            lines.append(f"- {signature(spec)}: {spec.description}" + (f" ({units})" if units else ""))
    return "\n".join(lines)


def system_prompt(registry: Registry = REGISTRY) -> str:
    return (
        "You are the planner of a robot manipulation system. Write ONE behavior tree that accomplishes the task.\n"
        'Answer with a JSON object {"task": <one line>, "tree": <node>} and nothing else. A node is either a\n'
        'composite {"type": "sequence"|"fallback"|"parallel", "children": [nodes], "arm"?: "left"|"right"} or a\n'
        'primitive {"type": <primitive name>, "params": {"arm"?: "left"|"right", <slot>: <value>}}.\n'
        "Slots marked * are required; others default to the value shown.\n\n"
        + grammar_listing(registry)
        + "\n\n"
        + GUIDANCE
    )


def user_prompt(request: PlanRequest) -> str:
    parts = []
    for instruction, plan_text in request.examples:
        parts.append(f"Example task: {instruction}\nExample plan:\n{plan_text.strip()}\n")
    if request.arms:
        arms = [
            f"{a} (base at x={x:.2f} m, y={y:.2f} m"
            + (f"; carries a mounted {request.tools[a]} and has no fingers" if a in request.tools else "")
            + ")"
            for a, (x, y) in sorted(request.arms.items())
        ]
        parts.append("The robot's arms: " + "; ".join(arms))
    parts.append("What perception sees now:\n" + (request.scene.summary or "(nothing reported)"))
    parts.append(f"Task: {request.instruction.strip()}")
    return "\n\n".join(parts)


def repair_prompt(errors: list[str]) -> str:
    return (
        "That plan does not type-check. Errors (path: problem):\n"
        + "\n".join(f"- {e}" for e in errors)
        + "\nReturn the corrected plan as the same JSON object, and nothing else."
    )


def response_schema() -> dict:
    return plan_json_schema()
