"""Canonical serialisation of plans (YAML in the paper's `task:` + `tree:` format, or plain dicts)."""

from __future__ import annotations

from typing import Any

import yaml

from .tree import Composite, Node, Plan


def node_to_dict(node: Node) -> dict[str, Any]:
    if isinstance(node, Composite):
        out: dict[str, Any] = {"type": node.type.value}
        if node.arm:
            out["arm"] = node.arm
        out["children"] = [node_to_dict(c) for c in node.children]
        return out
    out = {"primitive": node.primitive}
    if node.arm:
        out["arm"] = node.arm
    if node.params:
        order = [s.name for s in node.spec.slots]
        out["params"] = {k: node.params[k] for k in order if k in node.params}
    return out


def plan_to_dict(plan: Plan) -> dict[str, Any]:
    return {"task": plan.task, "tree": node_to_dict(plan.tree)}


def to_yaml(plan: Plan) -> str:
    """Canonical YAML: keys in a fixed order, params in registry slot order, only explicit params."""
    return yaml.safe_dump(plan_to_dict(plan), sort_keys=False, default_flow_style=False, allow_unicode=True, width=120)
