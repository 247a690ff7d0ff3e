"""Rigid poses in the world frame (position in metres, rotation as a 3x3 matrix)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class Pose:
    position_m: np.ndarray
    rotation: np.ndarray  # 3x3, columns are the frame's axes expressed in the world frame

    def translated(self, delta_m) -> Pose:
        return Pose(self.position_m + np.asarray(delta_m, float), self.rotation)


def rot_z(yaw_rad: float) -> np.ndarray:
    c, s = np.cos(yaw_rad), np.sin(yaw_rad)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


def rot_x(angle_rad: float) -> np.ndarray:
    c, s = np.cos(angle_rad), np.sin(angle_rad)
    return np.array([[1.0, 0.0, 0.0], [0.0, c, -s], [0.0, s, c]])


def rot_y(angle_rad: float) -> np.ndarray:
    c, s = np.cos(angle_rad), np.sin(angle_rad)
    return np.array([[c, 0.0, s], [0.0, 1.0, 0.0], [-s, 0.0, c]])


def top_down_rotation(yaw_rad: float = 0.0) -> np.ndarray:
    """Gripper pointing straight down (TCP z = world -z), fingers closing along world y rotated by `yaw_rad`."""
    return rot_z(yaw_rad) @ rot_x(np.pi)


def wrap_grasp_yaw(yaw_rad: float) -> float:
    """A parallel gripper is symmetric under a half turn: map any yaw into [-pi/2, pi/2)."""
    return float((yaw_rad + np.pi / 2) % np.pi - np.pi / 2)


def yaw_of(rotation: np.ndarray) -> float:
    """Yaw of a top-down gripper rotation (angle of its x axis about world z, sign-adjusted for the flip)."""
    return float(np.arctan2(rotation[1, 0], rotation[0, 0]))


def rotation_error(r_current: np.ndarray, r_target: np.ndarray) -> float:
    """Angle (rad) of the rotation taking current to target."""
    c = (np.trace(r_current.T @ r_target) - 1.0) / 2.0
    return float(np.arccos(np.clip(c, -1.0, 1.0)))
