"""Typed descriptions of primitives and their slots (the grammar's vocabulary)."""

from __future__ import annotations

import enum
import math
from dataclasses import dataclass, field
from typing import Any


class Tier(enum.StrEnum):
    BASE = "base"
    SKILL = "skill"
    RECOVERY = "recovery"
    BIMANUAL = "bimanual"


class ArmUse(enum.StrEnum):
    """Whether a primitive takes an `arm: left|right` tag."""

    NONE = "none"
    OPTIONAL = "optional"
    REQUIRED = "required"


class SlotType(enum.StrEnum):
    LABEL = "label"  # an object label, resolved to a 3D keypoint when the node runs
    NUMBER = "number"
    INTEGER = "integer"
    BOOL = "bool"
    ENUM = "enum"
    STRING = "string"


ARMS: tuple[str, ...] = ("left", "right")
MAX_LABEL_CHARS = 200


@dataclass(frozen=True)
class SlotSpec:
    """One named argument of a primitive. `unit` is SI (m, N, s, rad) or deg where stated."""

    name: str
    type: SlotType
    required: bool = False
    default: Any = None
    unit: str = ""
    minimum: float | None = None
    maximum: float | None = None
    values: tuple[str, ...] = ()
    doc: str = ""

    def expectation(self) -> str:
        """Human-readable statement of what a valid value looks like, used in error messages."""
        if self.type is SlotType.ENUM:
            return "one of " + ", ".join(self.values)
        if self.type in (SlotType.NUMBER, SlotType.INTEGER):
            kind = "number" if self.type is SlotType.NUMBER else "integer"
            if self.minimum is not None and self.maximum is not None:
                return f"{kind} in [{_fmt(self.minimum)}, {_fmt(self.maximum)}]"
            return kind
        if self.type is SlotType.LABEL:
            return f"non-empty object label (string of at most {MAX_LABEL_CHARS} characters)"
        if self.type is SlotType.BOOL:
            return "true or false"
        return "string"

    def accepts(self, value: Any) -> bool:
        """True when `value` is valid for this slot (type and range)."""
        t = self.type
        if t is SlotType.LABEL:
            return isinstance(value, str) and len(value.strip()) > 0 and len(value) <= MAX_LABEL_CHARS
        if t is SlotType.STRING:
            return isinstance(value, str) and len(value) <= 10_000
        if t is SlotType.BOOL:
            return isinstance(value, bool)
        if t is SlotType.ENUM:
            return isinstance(value, str) and value in self.values
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            return False
        if t is SlotType.INTEGER and not isinstance(value, int):
            return False
        if not math.isfinite(float(value)):
            return False
        if self.minimum is not None and value < self.minimum:
            return False
        return not (self.maximum is not None and value > self.maximum)

    def normalise(self, value: Any) -> Any:
        """Canonical in-memory form: numbers as float, everything else unchanged."""
        if self.type is SlotType.NUMBER:
            return float(value)
        return value


@dataclass(frozen=True)
class PrimitiveSpec:
    """Everything the system knows about one primitive; generated artefacts all derive from this."""

    name: str
    tier: Tier
    description: str
    arm: ArmUse
    timeout_s: float  # simulated seconds
    postcondition: str
    slots: tuple[SlotSpec, ...] = field(default_factory=tuple)
    perturbation: str | None = None  # tier-1 recovery primitive for contact primitives

    @property
    def uses_both_arms(self) -> bool:
        """Bimanual primitives without an arm tag drive both arms and cannot sit inside one arm's branch."""
        return self.tier is Tier.BIMANUAL and self.arm is ArmUse.NONE

    @property
    def label_slots(self) -> tuple[str, ...]:
        return tuple(s.name for s in self.slots if s.type is SlotType.LABEL)

    def slot(self, name: str) -> SlotSpec | None:
        for s in self.slots:
            if s.name == name:
                return s
        return None

    def defaults(self) -> dict[str, Any]:
        return {s.name: s.default for s in self.slots if s.default is not None}


def _fmt(x: float) -> str:
    return str(int(x)) if float(x).is_integer() else repr(float(x))
