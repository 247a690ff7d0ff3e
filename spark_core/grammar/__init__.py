"""The typed behavior-tree grammar: registry, tree nodes, parsing and type-checking, serialisation."""

from .errors import PlanError, PlanIssue
from .registry import REGISTRY, Registry, default_registry
from .schema import plan_json_schema
from .serialize import plan_to_dict, to_yaml
from .spec import ARMS, ArmUse, PrimitiveSpec, SlotSpec, SlotType, Tier
from .tree import Composite, CompositeType, Node, Plan, PrimitiveCall, walk
from .typecheck import check_plan, parse_plan, validate

__all__ = [
    "ARMS",
    "ArmUse",
    "Composite",
    "CompositeType",
    "Node",
    "Plan",
    "PlanError",
    "PlanIssue",
    "PrimitiveCall",
    "PrimitiveSpec",
    "REGISTRY",
    "Registry",
    "SlotSpec",
    "SlotType",
    "Tier",
    "check_plan",
    "default_registry",
    "parse_plan",
    "plan_json_schema",
    "plan_to_dict",
    "to_yaml",
    "validate",
    "walk",
]
