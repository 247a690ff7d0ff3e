"""What the planner gets to see: perception run on the phrases an instruction mentions.

The planner never receives a ground-truth object list: each noun phrase of the instruction (and the parts an
action needs, e.g. a drawer's handle) is handed to perception, and only what perception finds is in the view.
"""

from __future__ import annotations

from collections.abc import Sequence

from ..perception import Keypoint, LabelNotFound
from ..perception.resolver_protocol import Resolver
from ..perception.summary import summarise
from .protocol import SceneView
from .rules.parse import ParseError, is_pronoun, parse_instruction

PART_OF_ACTION = {"open": "handle", "close": "handle", "turn_on": "knob", "turn_off": "knob"}


def phrases_for(instruction: str) -> list[str]:
    """Noun phrases to look for: objects, targets, tools, sources, plus the part an action grips."""
    try:
        clauses = parse_instruction(instruction)
    except ParseError:
        return []
    out: dict[str, None] = {}
    for c in clauses:
        for p in (c.obj, c.target, c.tool, c.source):
            if p and not is_pronoun(p):
                out.setdefault(p, None)
        part = PART_OF_ACTION.get(c.action)
        if part and c.obj:
            out.setdefault(f"{c.obj} {part}", None)
            if "drawer" in c.obj:
                out.setdefault(f"drawer {part}", None)
    return list(out)


def observe(instruction: str, resolver: Resolver, extra: Sequence[str] = ()) -> SceneView:
    keypoints: dict[str, Keypoint] = {}
    for phrase in [*phrases_for(instruction), *extra]:
        try:
            keypoints[phrase] = resolver.resolve(phrase)
        except LabelNotFound:
            continue
    return SceneView(keypoints, summarise(keypoints) if keypoints else "perception found none of the objects mentioned")


def arm_bases(world) -> dict[str, tuple[float, float]]:
    """Where each arm stands (base x, y in the world, m): what a planner needs to share work between arms."""
    return {
        a: (float(world.kinematics[a].T_world_base[0, 3]), float(world.kinematics[a].T_world_base[1, 3]))
        for a in world.arms
    }


def arm_tools(world) -> dict[str, str]:
    """Arms that carry a tool fixed in place of fingers, and the tool: such an arm wipes but cannot grasp."""
    tools = {a: world.kinematics[a].robot.gripper.mounted_tool for a in world.arms}
    return {a: t for a, t in tools.items() if t}


def annotated_view(view: SceneView, resolver: Resolver) -> SceneView:
    """Multimodal planners also get the first camera's image with the detections drawn on it (when the
    resolver looks through cameras at all)."""
    frames = getattr(resolver, "frames", None)
    if not frames:
        return view
    from ..perception.annotate import annotate

    frame = next(iter(frames.values()))
    return SceneView(view.keypoints, view.summary, annotate(frame, [], view.keypoints))
