"""Training lists for the scorer, from the dev wording corpus: per instruction, every goal its scene view affords
(`candidates.options`), each labelled by whether its plan has the effect of the task's official wording's plan
(the wording bench's own check, `bench/wording.py`). Only dev files are read: the test half is never a training
example."""

from __future__ import annotations

import json
from collections.abc import Callable
from pathlib import Path
from typing import Any

from ...grammar import check_plan, plan_to_dict
from ..protocol import PlanRequest, SceneView
from ..rules.planner import RulesPlanner, composer
from .candidates import options


def affordances(request: PlanRequest, planner: RulesPlanner) -> list[tuple[str, list[dict]]]:
    """(plain goal, plan steps) for every distinct goal the request's scene view affords."""
    compose, effect = composer(planner, request)
    return [(c.text, children) for c, children in options(list(request.scene.keypoints), compose, effect)]


def collect(entries: list[dict[str, Any]], seed: int = 0, progress: Callable[[str], None] | None = None) -> list[dict]:
    """One example per entry whose task's official wording plans: its instruction, the plain goals, and which of
    them reach the official plan's effect; for an entry that expects a refusal (nonsense, an absent or an
    ambiguous thing) none does, and `refuse` is set: "none of these" is its answer."""
    from ...bench.wording import same_effect, signature
    from ...perception.factory import make_resolver
    from ...sim.tasks import SUITES
    from ..observe import arm_bases, arm_tools, observe

    planner = RulesPlanner(fallback=False)
    out: list[dict] = []
    by_task: dict[tuple[str, str], list[dict[str, Any]]] = {}
    for e in entries:
        if e["expect"] == "goal" or e["expect"].startswith("refuse"):
            by_task.setdefault((e["suite"], e["task"]), []).append(e)
    for (suite, name), group in by_task.items():
        world = SUITES[suite][name].make_world(seed)
        try:
            resolver = make_resolver(world, "sim", seed)
            arms, tools = arm_bases(world), arm_tools(world)

            def request(text: str, resolver=resolver, arms=arms, tools=tools) -> PlanRequest:
                return PlanRequest(text, observe(text, resolver), arms=arms, tools=tools)

            def sig(children: list[dict], view: SceneView) -> list:
                plan = check_plan({"task": "t", "tree": {"type": "sequence", "children": children}})
                return signature(plan_to_dict(plan), view)

            official = request(getattr(world, "instruction", SUITES[suite][name].instruction))
            ref = planner.plan(official)
            if ref.plan is None:
                continue
            ref_sig = signature(plan_to_dict(ref.plan), official.scene)
            for e in group:
                req = request(e["instruction"])
                refuse = e["expect"] != "goal"
                goals = []
                for text, children in affordances(req, planner):
                    try:
                        good = same_effect(sig(children, req.scene), ref_sig)
                    except ValueError:
                        continue
                    goals.append({"text": text, "good": bool(good) and not refuse})
                out.append({"id": e["id"], "instruction": e["instruction"], "goals": goals, "refuse": refuse})
                if progress:
                    progress(f"{e['id']}: {len(goals)} goals, {sum(1 for g in goals if g['good'])} good")
        finally:
            world.close()
    return out


def save(examples: list[dict], path: Path) -> None:
    path.write_text(json.dumps(examples, indent=0))
