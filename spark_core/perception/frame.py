"""A camera frame as perception consumes it (produced by a World's cameras)."""

from __future__ import annotations

from dataclasses import dataclass, field

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

    def project(self, points_world: np.ndarray) -> np.ndarray:
        """(N, 3) world points -> (N, 2) pixel coordinates (u, v)."""
        T = np.linalg.inv(self.T_world_camera)
        pc = np.asarray(points_world, float) @ T[:3, :3].T + T[:3, 3]
        return np.stack(
            [self.K[0, 0] * pc[:, 0] / pc[:, 2] + self.K[0, 2], self.K[1, 1] * pc[:, 1] / pc[:, 2] + self.K[1, 2]],
            axis=1,
        )
