"""Fusing two cameras' evidence for one label: only when both saw the same thing."""

from __future__ import annotations

import numpy as np

from spark_core.perception.detection import Detection
from spark_core.perception.lifting import PointEvidence
from spark_core.perception.resolver import fused_evidence


def _evidence(camera: str, centre_m: tuple[float, float, float], size_m: tuple[float, float, float], score: float):
    rng = np.random.default_rng(len(camera))
    pts = np.asarray(centre_m) + (rng.random((400, 3)) - 0.5) * np.asarray(size_m)
    det = Detection("handle", "handle", np.zeros((4, 4), bool), score, camera, False)
    return PointEvidence(det, pts, pts.mean(0))


def test_stacked_parts_in_two_views_are_not_fused():
    """Two handles one above the other (same xy, 7 cm apart in height): the less confident view's pick is
    another handle, not more evidence for the first one."""
    front = _evidence("agentview", (0.40, -0.17, 0.12), (0.08, 0.01, 0.015), 0.97)
    side = _evidence("frontview", (0.40, -0.17, 0.19), (0.08, 0.01, 0.015), 0.92)
    assert [e.detection.camera for e in fused_evidence([front, side])] == ["agentview"]


def test_a_tall_object_seen_from_above_and_from_the_side_is_fused():
    """A 30 cm bottle: the view from above sees mostly its upper part, the side view all of it; the medians'
    heights differ by more than 5 cm but by less than half its visible height."""
    above = _evidence("agentview", (0.50, 0.00, 0.20), (0.06, 0.06, 0.20), 0.9)
    side = _evidence("frontview", (0.51, 0.00, 0.13), (0.06, 0.06, 0.30), 0.8)
    assert len(fused_evidence([above, side])) == 2


def test_views_apart_in_xy_are_not_fused():
    a = _evidence("agentview", (0.40, 0.00, 0.02), (0.05, 0.05, 0.04), 0.9)
    b = _evidence("frontview", (0.50, 0.00, 0.02), (0.05, 0.05, 0.04), 0.8)
    assert [e.detection.camera for e in fused_evidence([a, b])] == ["agentview"]
