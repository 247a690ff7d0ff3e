"""Embodiments: which arms stand where. The one registry of robot set-ups; tasks, executor and primitives are
the same on every one (only the robot descriptions and base poses differ)."""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from ..control.panda import panda
from ..control.robot import RobotDescription
from ..control.ur10 import ur10


def _at(x: float, y: float, yaw_rad: float = 0.0) -> np.ndarray:
    """Base pose (4x4, world frame, metres) on the table plane."""
    T = np.eye(4)
    c, s = np.cos(yaw_rad), np.sin(yaw_rad)
    T[:3, :3] = [[c, -s, 0], [s, c, 0], [0, 0, 1]]
    T[:2, 3] = [x, y]
    return T


EMBODIMENTS: dict[str, Callable[[], dict[str, tuple[RobotDescription, np.ndarray]]]] = {
    "panda": lambda: {"right": (panda(), np.eye(4))},
    "ur10": lambda: {"right": (ur10(), np.eye(4))},
    # Two Pandas side by side behind the table edge, 0.6 m apart, both facing +x over the shared workspace.
    "bimanual": lambda: {"left": (panda(), _at(0.0, 0.3)), "right": (panda(), _at(0.0, -0.3))},
}


def robots_for(embodiment: str) -> dict[str, tuple[RobotDescription, np.ndarray]]:
    try:
        return EMBODIMENTS[embodiment]()
    except KeyError:
        raise ValueError(f"unknown embodiment {embodiment!r}; available: {', '.join(EMBODIMENTS)}") from None
