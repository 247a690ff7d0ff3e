"""Type-check plan data into a `Plan`, collecting every issue with its exact path.

A leaf is written in the paper's form, `{type: <primitive>, params: {arm: left, <slot>: <value>}}`, or in the
older `{primitive: <name>, params: {...}, arm: left}`; both give the same `PrimitiveCall`. `arm` may sit on the node
or inside `params` (not both with different values). A `type` that names a composite (sequence, parallel,
fallback) makes a composite node; any other `type` names a primitive."""

from __future__ import annotations

import difflib
import json
from typing import Any, cast

from .errors import PlanError, PlanIssue
from .loading import decode, load_text, unwrap
from .registry import REGISTRY, Registry
from .spec import ARMS, ArmUse
from .tree import Composite, CompositeType, Node, Plan, PrimitiveCall, child_path

MAX_TREE_DEPTH = 24  # each tree level is two YAML containers; stays under loading.MAX_NESTING
MAX_NODES = 2000
_TOP_KEYS = ("task", "tree")
_PRIMITIVE_KEYS = ("type", "params", "arm")  # the paper's leaf form; "primitive" replaces "type" in the old one
_OLD_PRIMITIVE_KEYS = ("primitive", "params", "arm")
_COMPOSITE_KEYS = ("type", "children", "arm")


def show(value: Any) -> str:
    """Compact JSON-ish rendering of a bad value for error messages (truncated)."""
    try:
        text = json.dumps(value, ensure_ascii=False, default=str)
    except (TypeError, ValueError):
        text = repr(value)
    return text if len(text) <= 60 else text[:57] + "..."


def _did_you_mean(word: str, options: list[str]) -> str:
    close = difflib.get_close_matches(word, options, n=1, cutoff=0.6)
    return f" (did you mean {close[0]!r}?)" if close else ""


class _Checker:
    def __init__(self, registry: Registry):
        self.reg = registry
        self.issues: list[PlanIssue] = []
        self.count = 0

    def err(self, path: str, message: str) -> None:
        self.issues.append(PlanIssue(path, message))

    # -- nodes -------------------------------------------------------------------------------------------------
    def node(self, raw: Any, path: str, depth: int, scope_arm: str | None) -> Node | None:
        self.count += 1
        if self.count > MAX_NODES:
            if self.count == MAX_NODES + 1:
                self.err(path, f"plan has more than {MAX_NODES} nodes")
            return None
        if depth > MAX_TREE_DEPTH:
            self.err(path, f"tree nested deeper than {MAX_TREE_DEPTH} levels")
            return None
        if not isinstance(raw, dict):
            self.err(path, f"expected a node (mapping with 'primitive' or 'type'), got {show(raw)}")
            return None
        if "primitive" in raw and "type" in raw:
            self.err(path, "a node names its kind once: 'type' (a composite or a primitive) or 'primitive', not both")
            return None
        if "primitive" not in raw and "type" not in raw:
            self.err(path, f"node needs 'primitive' or 'type'; got keys {show(sorted(map(str, raw)))}")
            return None
        arm = self.arm_tag(raw, path, scope_arm)
        if "primitive" in raw:
            return self.primitive(raw, path, "primitive", arm, scope_arm)
        t = raw["type"]
        kinds = [c.value for c in CompositeType]
        if isinstance(t, str) and t not in kinds and (t in self.reg or "children" not in raw):
            return self.primitive(raw, path, "type", arm, scope_arm)
        return self.composite(raw, path, depth, scope_arm, arm)

    def arm_tag(self, raw: dict, path: str, scope_arm: str | None) -> str | None:
        if "arm" not in raw:
            return None
        return self.arm_value(raw["arm"], f"{path}.arm", scope_arm)

    def arm_value(self, arm: Any, path: str, scope_arm: str | None) -> str | None:
        if arm not in ARMS:
            self.err(path, f"expected one of {', '.join(ARMS)}, got {show(arm)}")
            return None
        if scope_arm is not None and arm != scope_arm:
            self.err(path, f"arm {arm!r} inside a branch that belongs to arm {scope_arm!r}")
            return None
        return cast(str, arm)

    def composite(self, raw: dict, path: str, depth: int, scope_arm: str | None, arm: str | None) -> Node | None:
        for key in raw:
            if key not in _COMPOSITE_KEYS:
                self.err(
                    f"{path}.{key}", f"unknown key for a composite node{_did_you_mean(str(key), list(_COMPOSITE_KEYS))}"
                )
        kinds = [c.value for c in CompositeType]
        t = raw["type"]
        if t not in kinds:
            hint = _did_you_mean(str(t), kinds) if isinstance(t, str) else ""
            self.err(f"{path}.type", f"expected one of {', '.join(kinds)}, got {show(t)}{hint}")
            return None
        kind = CompositeType(t)
        children = raw.get("children")
        if children is None:
            self.err(f"{path}.children", f"missing required key: a {t} needs a list of children")
            return None
        if not isinstance(children, list):
            self.err(f"{path}.children", f"expected a list of nodes, got {show(children)}")
            return None
        if not children:
            self.err(f"{path}.children", f"a {t} needs at least one child")
            return None
        inner_scope = arm if arm is not None else scope_arm
        nodes = [self.node(c, child_path(path, i), depth + 1, inner_scope) for i, c in enumerate(children)]
        if kind is CompositeType.PARALLEL:
            self.parallel_arms(children, nodes, path, inner_scope)
        if any(n is None for n in nodes):
            return None
        return Composite(kind, tuple(nodes), arm)  # type: ignore[arg-type]

    def parallel_arms(self, raw_children: list, nodes: list[Node | None], path: str, scope_arm: str | None) -> None:
        """Each parallel branch belongs to exactly one arm, and the branches' arms are distinct."""
        seen: dict[str, int] = {}
        for i, node in enumerate(nodes):
            if node is None:
                continue
            cpath = child_path(path, i)
            arms = _arms_used(node)
            if not arms:
                self.err(f"{cpath}.arm", f"each parallel branch needs an arm tag ({' or '.join(ARMS)})")
            elif len(arms) > 1:
                self.err(cpath, f"a parallel branch must use one arm, this one uses {', '.join(sorted(arms))}")
            else:
                (a,) = arms
                if a in seen:
                    self.err(
                        f"{cpath}.arm",
                        f"arm {a!r} already runs branch children[{seen[a]}]; parallel branches need distinct arms",
                    )
                else:
                    seen[a] = i
        if scope_arm is not None and len(nodes) > 1:
            self.err(path, f"a parallel with several branches cannot run inside arm {scope_arm!r}'s branch")

    def primitive(
        self, raw: dict, path: str, name_key: str, node_arm: str | None, scope_arm: str | None
    ) -> PrimitiveCall | None:
        """A leaf; its name is under `name_key` ("type" in the paper's form, "primitive" in the old one)."""
        keys = _PRIMITIVE_KEYS if name_key == "type" else _OLD_PRIMITIVE_KEYS
        for key in raw:
            if key not in keys:
                self.err(f"{path}.{key}", f"unknown key for a primitive node{_did_you_mean(str(key), list(keys))}")
        name = raw[name_key]
        if not isinstance(name, str):
            self.err(f"{path}.{name_key}", f"expected a primitive name, got {show(name)}")
            return None
        spec = self.reg.get(name)
        if spec is None:
            options = self.reg.names() + ([c.value for c in CompositeType] if name_key == "type" else [])
            self.err(f"{path}.{name_key}", f"unknown primitive {name!r}{_did_you_mean(name, options)}")
            return None
        params_raw = raw.get("params", {})
        if params_raw is None:
            params_raw = {}
        if not isinstance(params_raw, dict):
            self.err(f"{path}.params", f"expected a mapping of slot names to values, got {show(params_raw)}")
            return None
        ok = True
        explicit_arm, arm_path = node_arm, f"{path}.arm"
        if "arm" in params_raw:  # the paper's form: the arm is one of the params
            arm_path = f"{path}.params.arm"
            in_params = self.arm_value(params_raw["arm"], arm_path, scope_arm)
            if in_params is None:
                ok = False
            elif node_arm is not None and in_params != node_arm:
                self.err(arm_path, f"arm {in_params!r} disagrees with the node's arm {node_arm!r}")
                ok = False
            explicit_arm = in_params if in_params is not None else node_arm
            params_raw = {k: v for k, v in params_raw.items() if k != "arm"}
        arm = explicit_arm if explicit_arm is not None else scope_arm
        if explicit_arm is not None and spec.arm is ArmUse.NONE:
            self.err(arm_path, f"{name} does not take an arm tag")
            ok = False
        if spec.arm is ArmUse.REQUIRED and arm is None:
            self.err(
                f"{path}.params.arm" if name_key == "type" else arm_path,
                f"{name} needs an arm tag ({' or '.join(ARMS)}) in its params, on the node or on its branch",
            )
            ok = False
        if spec.uses_both_arms and arm is not None:
            self.err(path, f"{name} drives both arms and cannot run inside arm {arm!r}'s branch")
            ok = False
        params: dict[str, Any] = {}
        slot_names = [s.name for s in spec.slots]
        for key, value in params_raw.items():
            slot = spec.slot(key) if isinstance(key, str) else None
            if slot is None:
                hint = _did_you_mean(str(key), slot_names)
                valid = f"; {name} takes {', '.join(slot_names)}" if slot_names else f"; {name} takes no params"
                self.err(f"{path}.params.{key}", f"unknown slot{hint}{valid}")
                ok = False
                continue
            if value is None and not slot.required:
                continue  # explicit null = "use the default / auto"
            if not slot.accepts(value):
                self.err(f"{path}.params.{key}", f"expected {slot.expectation()}, got {show(value)}")
                ok = False
                continue
            params[key] = slot.normalise(value)
        for slot in spec.slots:
            if slot.required and params_raw.get(slot.name) is None and slot.name not in params:
                self.err(f"{path}.params.{slot.name}", f"missing required slot of {name} ({slot.expectation()})")
                ok = False
        if name == "handoff" and params.get("from_arm") is not None and params.get("from_arm") == params.get("to_arm"):
            self.err(f"{path}.params.to_arm", "handoff needs two different arms")
            ok = False
        return PrimitiveCall(name, params, explicit_arm) if ok else None

    # -- top level ---------------------------------------------------------------------------------------------
    def plan(self, data: Any) -> Plan | None:
        if not isinstance(data, dict):
            self.err("plan", f"expected a mapping with 'task' and 'tree', got {show(data)}")
            return None
        for key in data:
            if key not in _TOP_KEYS:
                self.err(
                    str(key),
                    f"unknown top-level key{_did_you_mean(str(key), list(_TOP_KEYS))}; a plan has task and tree",
                )
        task = data.get("task")
        if task is None:
            self.err("task", "missing required key: a one-line task description")
        elif not isinstance(task, str) or not task.strip():
            self.err("task", f"expected a non-empty string, got {show(task)}")
        if "tree" not in data:
            self.err("tree", "missing required key: the behavior tree")
            return None
        tree = self.node(data["tree"], "tree", 0, None)
        if tree is None or self.issues:
            return None
        return Plan(task=cast(str, task), tree=tree)  # a str: any other value was reported above


def _arms_used(node: Node) -> set[str]:
    """Arms a subtree is tagged with (its own tag wins over its descendants')."""
    if node.arm is not None:
        return {node.arm}
    if isinstance(node, PrimitiveCall):
        return set()
    out: set[str] = set()
    for c in node.children:
        out |= _arms_used(c)
    return out


def check_plan(data: Any, registry: Registry = REGISTRY) -> Plan:
    """Type-check already-loaded data. Raises PlanError listing every issue."""
    checker = _Checker(registry)
    plan = checker.plan(data)
    if plan is None:
        raise PlanError(checker.issues or [PlanIssue("plan", "invalid plan")])
    return plan


def parse_plan(text: str | bytes, registry: Registry = REGISTRY) -> Plan:
    """Text (YAML or JSON, optionally fenced or wrapped by an LLM) -> typed Plan, or PlanError."""
    return check_plan(unwrap(load_text(decode(text))), registry)


def validate(text: str | bytes, registry: Registry = REGISTRY) -> tuple[Plan | None, list[PlanIssue]]:
    """Like parse_plan but returns (plan, issues) instead of raising."""
    try:
        return parse_plan(text, registry), []
    except PlanError as e:
        return None, e.issues
