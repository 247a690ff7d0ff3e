"""Canonical serialisation of plans: the paper's format (`task:` + `tree:`; a leaf is `type: <primitive>` with its
arm inside `params`), as YAML or plain dicts. The older leaf form (`primitive: <name>`, `arm` on the node) is still
read everywhere, and written on request for readers that need it (`form="primitive"`)."""

from __future__ import annotations

import unicodedata
from typing import Any, Literal

import yaml

from .tree import Composite, Node, Plan

LeafForm = Literal["paper", "primitive"]


def node_to_dict(node: Node, form: LeafForm = "paper") -> dict[str, Any]:
    if isinstance(node, Composite):
        out: dict[str, Any] = {"type": node.type.value}
        if node.arm:
            out["arm"] = node.arm
        out["children"] = [node_to_dict(c, form) for c in node.children]
        return out
    order = [s.name for s in node.spec.slots]
    params = {k: node.params[k] for k in order if k in node.params}
    if form == "paper":
        out = {"type": node.primitive}
        if node.arm:
            params = {"arm": node.arm, **params}
    else:
        out = {"primitive": node.primitive}
        if node.arm:
            out["arm"] = node.arm
    if params:
        out["params"] = params
    return out


def plan_to_dict(plan: Plan, form: LeafForm = "paper") -> dict[str, Any]:
    return {"task": plan.task, "tree": node_to_dict(plan.tree, form)}


class _Dumper(yaml.SafeDumper):
    pass


class _FlowParams(dict):
    """A leaf's params, written on one line (`params: {arm: left, keypoint_label: fork}`) in the compact form."""


class _CompactDumper(_Dumper):
    def increase_indent(self, flow: bool = False, indentless: bool = False):
        return super().increase_indent(flow, False)  # `children:` items indented under their key


def _represent_str(dumper: yaml.SafeDumper, value: str) -> yaml.ScalarNode:
    # PyYAML emits some strings plain that it cannot read back (e.g. "0\xa0", ":\xa0"): double-quote any
    # string with non-ASCII spaces/controls or surrounding whitespace, so every label round-trips exactly.
    odd = value != value.strip() or any(unicodedata.category(c)[0] in "ZC" and c != " " for c in value)
    return dumper.represent_scalar("tag:yaml.org,2002:str", value, style='"' if odd else None)


_Dumper.add_representer(str, _represent_str)
_CompactDumper.add_representer(
    _FlowParams, lambda d, v: d.represent_mapping("tag:yaml.org,2002:map", v.items(), flow_style=True)
)


def _flow_params(node: dict[str, Any]) -> dict[str, Any]:
    out: dict[str, Any] = {}
    for key, value in node.items():
        if key == "children":
            value = [_flow_params(c) for c in value]
        elif key == "params":
            value = _FlowParams(value)
        out[key] = value
    return out


def to_yaml(plan: Plan, compact: bool = False) -> str:
    """Canonical YAML in the paper's form: keys in a fixed order, `arm` first in a leaf's params, then the params
    in registry slot order, only explicit params. `compact`: each leaf's params on one line and children indented
    under their key (the form of the checked-in plan files)."""
    data = plan_to_dict(plan)
    if compact:
        data = {"task": data["task"], "tree": _flow_params(data["tree"])}
    return yaml.dump(
        data,
        Dumper=_CompactDumper if compact else _Dumper,
        sort_keys=False,
        default_flow_style=False,
        allow_unicode=True,
        width=120,
    )
