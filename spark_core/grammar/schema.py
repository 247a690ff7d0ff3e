"""JSON Schema of a plan in the paper's form, generated from the registry (for structured LLM output and API docs).

A leaf is `{"type": <primitive>, "params": {"arm"?: "left"|"right", <slot>: <value>}}`; a composite is
`{"type": "sequence"|"parallel"|"fallback", "arm"?: ..., "children": [...]}`. (The type-checker also reads the
older leaf form, `{"primitive": <name>, "arm"?: ..., "params": {...}}`; the schema asks for the canonical one.)"""

from __future__ import annotations

from typing import Any

from .registry import REGISTRY, Registry
from .spec import ARMS, ArmUse, SlotSpec, SlotType
from .tree import CompositeType


def slot_schema(slot: SlotSpec) -> dict[str, Any]:
    t = slot.type
    s: dict[str, Any]
    if t is SlotType.NUMBER:
        s = {"type": "number"}
    elif t is SlotType.INTEGER:
        s = {"type": "integer"}
    elif t is SlotType.BOOL:
        s = {"type": "boolean"}
    elif t is SlotType.ENUM:
        s = {"type": "string", "enum": list(slot.values)}
    elif t is SlotType.LABEL:
        s = {"type": "string", "minLength": 1, "maxLength": 200}
    else:
        s = {"type": "string"}
    if slot.minimum is not None:
        s["minimum"] = slot.minimum
    if slot.maximum is not None:
        s["maximum"] = slot.maximum
    if slot.default is not None:
        s["default"] = slot.default
    desc = " ".join(x for x in (slot.doc, f"unit: {slot.unit}" if slot.unit else "") if x)
    if desc:
        s["description"] = desc
    return s


def plan_json_schema(registry: Registry = REGISTRY) -> dict[str, Any]:
    defs: dict[str, Any] = {}
    refs = []
    for spec in registry:
        slots: dict[str, Any] = {}
        if spec.arm is not ArmUse.NONE:
            need = "required here or on the enclosing branch" if spec.arm is ArmUse.REQUIRED else "optional"
            doc = f"the arm that runs this step ({need})"
            slots["arm"] = {"type": "string", "enum": list(ARMS), "description": doc}
        slots.update({s.name: slot_schema(s) for s in spec.slots})
        params: dict[str, Any] = {"type": "object", "properties": slots, "additionalProperties": False}
        required_slots = [s.name for s in spec.slots if s.required]
        if required_slots:
            params["required"] = required_slots
        node = {
            "type": "object",
            "description": spec.description,
            "properties": {"type": {"const": spec.name}, "params": params},
            "required": ["type"] + (["params"] if required_slots else []),
            "additionalProperties": False,
        }
        defs[f"primitive_{spec.name}"] = node
        refs.append({"$ref": f"#/$defs/primitive_{spec.name}"})
    defs["composite"] = {
        "type": "object",
        "properties": {
            "type": {"type": "string", "enum": [c.value for c in CompositeType]},
            "arm": {"type": "string", "enum": list(ARMS)},
            "children": {"type": "array", "minItems": 1, "items": {"$ref": "#/$defs/node"}},
        },
        "required": ["type", "children"],
        "additionalProperties": False,
    }
    defs["node"] = {"anyOf": [{"$ref": "#/$defs/composite"}, *refs]}
    return {
        "$schema": "https://json-schema.org/draft/2020-12/schema",
        "title": "SPARK plan",
        "type": "object",
        "properties": {"task": {"type": "string", "minLength": 1}, "tree": {"$ref": "#/$defs/node"}},
        "required": ["task", "tree"],
        "additionalProperties": False,
        "$defs": defs,
    }
