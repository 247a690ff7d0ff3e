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


class _TwoBowls:
    """A segmenter that sees two look-alike instances for any prompt: left half and right half of the frame."""

    name, privileged = "two", False

    def segment(self, frame, prompts):
        out = []
        for p in prompts:
            for cols in (slice(0, 40), slice(120, 160)):
                m = np.zeros(frame.shape, bool)
                m[40:80, cols] = True
                out.append(Detection(p, p, m, 0.9, frame.camera, False))
        return out


def _flat_frame():
    from spark_core.perception.frame import CameraFrame

    K = np.array([[100.0, 0, 80], [0, 100.0, 60], [0, 0, 1]])
    T = np.eye(4)
    T[:3, :3] = np.diag([1.0, -1.0, -1.0])
    T[2, 3] = 1.0
    return CameraFrame("top", np.zeros((120, 160, 3), np.uint8), np.ones((120, 160), np.float32), K, T)


def test_ambiguous_prompts_keep_the_instance_where_the_object_was_last_seen():
    from spark_core.perception.adaptive import select_prompt

    frame = _flat_frame()
    assert select_prompt(_TwoBowls(), frame, "bowl", ["round bowl"]).detection is None  # ambiguous, no history
    left = frame.backproject(np.array([20.0]), np.array([60.0]), np.array([1.0]))[0]
    sel = select_prompt(_TwoBowls(), frame, "bowl", ["round bowl"], seen_at_m=left + [0.02, 0.0, 0.0])
    assert sel.detection is not None and np.nonzero(sel.detection.mask)[1].max() < 40
    assert "tracked" in {c.verdict for c in sel.candidates}
    far = left + [0.0, 0.0, 0.5]  # nothing near where it was: still ambiguous
    assert select_prompt(_TwoBowls(), frame, "bowl", ["round bowl"], seen_at_m=far).detection is None
