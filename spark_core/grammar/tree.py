"""Behavior-tree nodes and the typed Plan. Trees are plain data: print, walk and serialise them."""

from __future__ import annotations

import enum
from collections.abc import Iterator
from dataclasses import dataclass, field
from typing import Any

from .registry import REGISTRY
from .spec import PrimitiveSpec


class CompositeType(enum.StrEnum):
    SEQUENCE = "sequence"  # children in order; fails at the first failing child
    PARALLEL = "parallel"  # arm-tagged branches run concurrently, joined at an implicit barrier
    FALLBACK = "fallback"  # children in order until one succeeds


@dataclass(frozen=True)
class PrimitiveCall:
    """A leaf: one primitive with its explicitly given params (defaults are applied by `args`)."""

    primitive: str
    params: dict[str, Any] = field(default_factory=dict)
    arm: str | None = None  # explicit tag on this node; see Plan.arm_of for the effective arm

    @property
    def spec(self) -> PrimitiveSpec:
        return REGISTRY[self.primitive]

    @property
    def args(self) -> dict[str, Any]:
        """Params with registry defaults filled in."""
        return {**self.spec.defaults(), **self.params}

    @property
    def labels(self) -> list[str]:
        """Object labels this call names (resolved to keypoints when it runs)."""
        args = self.args
        return [args[s] for s in self.spec.label_slots if args.get(s) is not None]


@dataclass(frozen=True)
class Composite:
    type: CompositeType
    children: tuple[Node, ...]
    arm: str | None = None


Node = PrimitiveCall | Composite


def child_path(parent: str, index: int) -> str:
    return f"{parent}.children[{index}]"


def walk(node: Node, path: str = "tree", arm: str | None = None) -> Iterator[tuple[str, Node, str | None]]:
    """Depth-first (path, node, effective arm) triples, the root first."""
    arm = node.arm or arm
    yield path, node, arm
    if isinstance(node, Composite):
        for i, c in enumerate(node.children):
            yield from walk(c, child_path(path, i), arm)


@dataclass(frozen=True)
class Plan:
    """A type-checked behavior tree for one task."""

    task: str
    tree: Node

    def nodes(self) -> list[tuple[str, Node, str | None]]:
        return list(walk(self.tree))

    def primitives(self) -> list[tuple[str, PrimitiveCall, str | None]]:
        return [(p, n, a) for p, n, a in walk(self.tree) if isinstance(n, PrimitiveCall)]

    def labels(self) -> list[str]:
        """Every distinct object label the plan names, in first-use order."""
        seen: dict[str, None] = {}
        for _, call, _ in self.primitives():
            for label in call.labels:
                seen.setdefault(label, None)
        return list(seen)

    def node_at(self, path: str) -> Node:
        for p, n, _ in walk(self.tree):
            if p == path:
                return n
        raise KeyError(path)
