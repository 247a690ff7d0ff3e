"""PRIVILEGED resolver: label -> keypoint from simulator ground truth. For testing control alone; every
keypoint it returns is marked `privileged:sim-state`, and every figure produced with it must say so."""

from __future__ import annotations

from typing import Any

import numpy as np

from .keypoint import Keypoint, LabelNotFound

SOURCE = "privileged:sim-state"


class PrivilegedResolver:
    """Reads object and part poses straight from the simulated world (no cameras, no noise)."""

    privileged = True

    def __init__(self, world):
        self.world = world
        scene = world.scene
        self._bodies: dict[str, str] = {label.lower(): o.body for label, o in scene.objects.items()}
        self._bodies.update({label.lower(): body for label, (body, _) in scene.parts.items()})
        self.refreshes = 0

    def labels(self) -> list[str]:
        return sorted(self._bodies)

    def refresh(self) -> None:
        self.refreshes += 1  # ground truth is always current; counted so tests can see re-detection happen

    def resolve(self, label: str) -> Keypoint:
        body = self._bodies.get(label.strip().lower())
        if body is None:
            raise LabelNotFound(label, f"no object with that label in the scene (have: {', '.join(self.labels())})")
        geoms = self.world.body_geoms(body)
        if not geoms:
            raise LabelNotFound(label, "nothing of it is there any more (every part of it was removed or wiped)")
        lo, hi = self.world.body_aabb(body)
        R = self.world.body_rotation(body)
        yaw = float(np.arctan2(R[1, 0], R[0, 0]))
        # The object's own length and width (a turned object's world box overstates them) decide which side the
        # fingers close across; see Ctx.grasp_yaw.
        own = self.world.body_extent_m(body, yaw)
        detail: dict[str, Any] = {"body_extent_m": [round(float(x), 5) for x in own]}
        if len(geoms) > 1:  # a region made of pieces (Wipe's dirt): where each piece is, for covering it
            xy = self.world.data.geom_xpos[geoms, :2] - self.world.origin_m[:2]
            detail["footprint_xy_m"] = [[round(float(x), 4), round(float(y), 4)] for x, y in xy]
        return Keypoint(label, (lo + hi) / 2, hi - lo, yaw, SOURCE, detail=detail)
