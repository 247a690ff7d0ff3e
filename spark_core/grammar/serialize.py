"""Canonical serialisation of plans (YAML in the paper's `task:` + `tree:` format, or plain dicts)."""

from __future__ import annotations

import unicodedata
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


class _Dumper(yaml.SafeDumper):
    pass


def _represent_str(dumper: yaml.SafeDumper, value: str) -> yaml.ScalarNode:
    # PyYAML emits some strings plain that it cannot read back (e.g. "0\xa0", ":\xa0"): double-quote any
    # string with non-ASCII spaces/controls or surrounding whitespace, so every label round-trips exactly.
    odd = value != value.strip() or any(unicodedata.category(c)[0] in "ZC" and c != " " for c in value)
    return dumper.represent_scalar("tag:yaml.org,2002:str", value, style='"' if odd else None)


_Dumper.add_representer(str, _represent_str)


def to_yaml(plan: Plan) -> str:
    """Canonical YAML: keys in a fixed order, params in registry slot order, only explicit params."""
    return yaml.dump(
        plan_to_dict(plan), Dumper=_Dumper, sort_keys=False, default_flow_style=False, allow_unicode=True, width=120
    )
