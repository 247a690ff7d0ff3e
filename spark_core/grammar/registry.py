"""The primitive registry: loaded once from `primitives.yaml`, the single source of truth of the grammar."""

from __future__ import annotations

from collections.abc import Mapping
from functools import lru_cache
from importlib import resources
from types import MappingProxyType

import yaml

from .spec import ArmUse, PrimitiveSpec, SlotSpec, SlotType, Tier


class Registry:
    """Read-only mapping of primitive name -> PrimitiveSpec, in declaration order."""

    def __init__(self, specs: list[PrimitiveSpec]):
        self._specs: Mapping[str, PrimitiveSpec] = MappingProxyType({s.name: s for s in specs})

    def __contains__(self, name: object) -> bool:
        return name in self._specs

    def __getitem__(self, name: str) -> PrimitiveSpec:
        return self._specs[name]

    def get(self, name: str) -> PrimitiveSpec | None:
        return self._specs.get(name)

    def __iter__(self):
        return iter(self._specs.values())

    def __len__(self) -> int:
        return len(self._specs)

    def names(self) -> list[str]:
        return list(self._specs)

    def by_tier(self, tier: Tier) -> list[PrimitiveSpec]:
        return [s for s in self._specs.values() if s.tier is tier]


def _slot(name: str, raw: dict) -> SlotSpec:
    t = SlotType(raw["type"])
    return SlotSpec(
        name=name,
        type=t,
        required=bool(raw.get("required", False)),
        default=raw.get("default"),
        unit=raw.get("unit", ""),
        minimum=raw.get("min"),
        maximum=raw.get("max"),
        values=tuple(raw.get("values", ())),
        doc=raw.get("doc", ""),
    )


RESERVED_SLOT_NAMES = frozenset({"arm"})  # `params.arm` is a plan's arm tag (the paper's form), never a slot


def load_registry(text: str) -> Registry:
    data = yaml.safe_load(text)
    specs: list[PrimitiveSpec] = []
    for tier_name, prims in data.items():
        tier = Tier(tier_name)
        for name, raw in prims.items():
            reserved = RESERVED_SLOT_NAMES & set(raw.get("slots") or {})
            if reserved:
                raise ValueError(f"primitive {name}: slot name(s) {', '.join(sorted(reserved))} are reserved")
            specs.append(
                PrimitiveSpec(
                    name=name,
                    tier=tier,
                    description=raw["description"],
                    arm=ArmUse(raw["arm"]),
                    timeout_s=float(raw["timeout_s"]),
                    postcondition=raw["postcondition"],
                    slots=tuple(_slot(n, s) for n, s in (raw.get("slots") or {}).items()),
                    perturbation=raw.get("perturbation"),
                )
            )
    return Registry(specs)


@lru_cache(maxsize=1)
def default_registry() -> Registry:
    text = resources.files(__package__).joinpath("primitives.yaml").read_text(encoding="utf-8")
    return load_registry(text)


REGISTRY = default_registry()
