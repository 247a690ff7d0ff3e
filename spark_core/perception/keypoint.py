"""A label resolved to a 3D keypoint in the world frame."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np


@dataclass(frozen=True)
class Keypoint:
    """Where a labelled object is, as perception (or a privileged oracle) sees it now.

    position_m: object centre in the world frame (m).
    extent_m: axis-aligned full size (x, y, z) in the world frame (m).
    yaw_rad: rotation of the object's principal axis about world z; None when unstable/unknown.
    top_z_m: height of the object's top surface in the world frame (m).
    source: where it came from ("privileged:sim-state", "sim", "sam3", ...), so figures can say which protocol.
    """

    label: str
    position_m: np.ndarray
    extent_m: np.ndarray = field(default_factory=lambda: np.zeros(3))
    yaw_rad: float | None = None
    source: str = ""
    score: float = 1.0
    detail: dict[str, Any] = field(default_factory=dict)

    @property
    def own_extent_xy_m(self) -> list[float] | None:
        """The object's own length along `yaw_rad` and width across it: the body's (privileged) or the seen top
        face's; None when neither is known. The world-axis `extent_m` overstates a turned object and cannot tell
        which side is long."""
        return self.detail.get("body_extent_m") or self.detail.get("principal_extent_m")

    @property
    def top_z_m(self) -> float:
        return float(self.position_m[2] + self.extent_m[2] / 2)

    def to_dict(self) -> dict[str, Any]:
        return {
            "label": self.label,
            "position_m": [round(float(x), 5) for x in self.position_m],
            "extent_m": [round(float(x), 5) for x in self.extent_m],
            "yaw_rad": None if self.yaw_rad is None else round(float(self.yaw_rad), 5),
            "source": self.source,
            "score": round(float(self.score), 4),
        }


class LabelNotFound(LookupError):
    """Perception could not resolve a label to exactly one object."""

    def __init__(self, label: str, reason: str = "no confident detection"):
        self.label = label
        self.reason = reason
        super().__init__(f"label {label!r} not resolved: {reason}")
