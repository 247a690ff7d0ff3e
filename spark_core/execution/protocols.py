"""The seams the executor runs against: how labels become keypoints (the Resolver protocol, defined in perception
where planning sees it too) and how primitives become motion."""

from __future__ import annotations

import enum
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any, Protocol, runtime_checkable

from ..grammar import PrimitiveCall
from ..perception import Keypoint
from ..perception.resolver_protocol import Resolver

__all__ = ["ActionOutcome", "Actuator", "FailureKind", "Resolver"]


class FailureKind(enum.StrEnum):
    """Which module a failure is attributed to."""

    PLANNER = "planner"
    PERCEPTION = "perception"
    CONTROL = "control"
    KINEMATIC_LIMIT = "kinematic_limit"
    COLLISION = "collision"  # the motion would bring two arms together (refused before moving)
    TIMEOUT = "timeout"


@dataclass
class ActionOutcome:
    """Result of performing one primitive: did its post-condition hold, and how long it took in sim time."""

    ok: bool
    sim_time_s: float = 0.0
    reason: str = ""
    failure: FailureKind | None = None
    detail: dict[str, Any] = field(default_factory=dict)

    @classmethod
    def success(cls, sim_time_s: float, **detail: Any) -> ActionOutcome:
        return cls(True, sim_time_s, "", None, detail)

    @classmethod
    def fail(
        cls, reason: str, failure: FailureKind = FailureKind.CONTROL, sim_time_s: float = 0.0, **detail: Any
    ) -> ActionOutcome:
        return cls(False, sim_time_s, reason, failure, detail)


@runtime_checkable
class Actuator(Protocol):
    """Performs one primitive on an embodiment and checks its post-condition from sensed state.

    Implementations: the physics world's primitive library (spark_core.execution.primitives) and, in tests,
    a kinematic double. Must be safe to call from one thread per arm concurrently.
    """

    arms: tuple[str, ...]

    def perform(
        self, call: PrimitiveCall, keypoints: Mapping[str, Keypoint], arm: str, timeout_s: float
    ) -> ActionOutcome: ...
