"""A camera frame as perception consumes it (produced by a World's cameras)."""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import cached_property

import numpy as np


@dataclass(frozen=True)
class CameraFrame:
    """One rendered/captured view. Pixel (u, v) = (column, row); camera frame x right, y down, z forward.

    `object_ids`/`labels` exist only where the world has per-pixel ground truth (simulation); anything that
    uses them is privileged.
    """

    camera: str
    rgb: np.ndarray  # (H, W, 3) uint8
    depth_m: np.ndarray  # (H, W) float32, metres along the optical axis
    K: np.ndarray  # 3x3 intrinsics (pixels)
    T_world_camera: np.ndarray  # 4x4
    sim_time_s: float = 0.0
    object_ids: np.ndarray | None = None  # (H, W) int32, 0 = none (privileged)
    labels: dict[int, str] = field(default_factory=dict)  # object id -> label (privileged)

    @property
    def shape(self) -> tuple[int, int]:
        return self.rgb.shape[:2]

    def backproject(self, us: np.ndarray, vs: np.ndarray, z: np.ndarray) -> np.ndarray:
        """Pixels with depth -> (N, 3) world points (m)."""
        K = self.K
        pts = np.stack([(us - K[0, 2]) * z / K[0, 0], (vs - K[1, 2]) * z / K[1, 1], z], axis=1)
        return pts @ self.T_world_camera[:3, :3].T + self.T_world_camera[:3, 3]

    @cached_property
    def height_map_m(self) -> np.ndarray:
        """(H, W) world height z (m) of every pixel, NaN where the depth is missing; computed once per frame.

        z_world = depth * (R[2] . ray(u, v)) + t_z, and the ray's z-row term is a sum of a per-column and a per-row
        part, so the map costs two broadcasts instead of backprojecting every pixel."""
        K, R, t = self.K, self.T_world_camera[:3, :3], self.T_world_camera[:3, 3]
        H, W = self.shape
        col = R[2, 0] * (np.arange(W) - K[0, 2]) / K[0, 0]
        row = R[2, 1] * (np.arange(H) - K[1, 2]) / K[1, 1] + R[2, 2]
        depth = self.depth_m.astype(np.float64)
        ok = np.isfinite(depth) & (depth > 0)
        return np.where(ok, depth * (row[:, None] + col[None, :]) + t[2], np.nan)

    def project(self, points_world: np.ndarray) -> np.ndarray:
        """(N, 3) world points -> (N, 2) pixel coordinates (u, v)."""
        T = np.linalg.inv(self.T_world_camera)
        pc = np.asarray(points_world, float) @ T[:3, :3].T + T[:3, 3]
        return np.stack(
            [self.K[0, 0] * pc[:, 0] / pc[:, 2] + self.K[0, 2], self.K[1, 1] * pc[:, 1] / pc[:, 2] + self.K[1, 2]],
            axis=1,
        )
