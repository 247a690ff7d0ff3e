"""What the rules-planner tests hand the planner and read back: a scene view of keypoints put where the test says,
and the plan's leaves."""

import numpy as np

from spark_core.grammar import plan_to_dict
from spark_core.perception import Keypoint
from spark_core.planning import PlanRequest, SceneView
from spark_core.planning.rules import RulesPlanner


def view(inventory=(), unresolved=None, **where) -> SceneView:
    """Keypoints named by the keyword (underscores read as spaces) at the given world positions (m), 5 cm boxes;
    `unresolved` what perception could not single out and why; `inventory` what the scene is said to hold."""
    kps = {k.replace("_", " "): Keypoint(k, np.array(v, float), np.full(3, 0.05)) for k, v in where.items()}
    return SceneView(kps, unresolved=unresolved or {}, inventory=inventory)


def leaves(result) -> list[tuple[str, str | None]]:
    """(primitive, its label) for each leaf of the plan, in order."""
    out: list[tuple[str, str | None]] = []

    def walk(node: dict) -> None:
        if "children" in node:
            for child in node["children"]:
                walk(child)
            return
        params = node.get("params", {})
        out.append((node["type"], next((v for k, v in params.items() if k.endswith("label")), None)))

    walk(plan_to_dict(result.plan)["tree"])
    return out


def plan(text: str, scene: SceneView):
    """The rules planner's answer for `text` in `scene`."""
    return RulesPlanner().plan(PlanRequest(text, scene))
