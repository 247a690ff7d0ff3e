"""Covering a flat region with a tool of a given width: serpentine strokes over its footprint."""

from __future__ import annotations

import numpy as np


def coverage_strokes(
    footprint_xy_m: np.ndarray, stripe_m: float, margin_m: float = 0.03
) -> tuple[list[np.ndarray], float]:
    """Waypoints (xy, m) of a serpentine that passes a tool `stripe_m` wide (across the motion) over every point
    of the footprint, and the stroke direction (rad about world z).

    Strokes run along the footprint's principal axis, so a long trail is covered in few long strokes; stripes
    without any point are skipped, and each stroke spans only its stripe's points (plus `margin_m` at each end,
    so the tool's leading edge clears the last point)."""
    pts = np.asarray(footprint_xy_m, float).reshape(-1, 2)
    if len(pts) == 0:
        return [], 0.0
    centre = pts.mean(axis=0)
    if len(pts) >= 3 and np.ptp(pts, axis=0).max() > 1e-6:
        _, vecs = np.linalg.eigh(np.cov((pts - centre).T))
        u = vecs[:, -1]  # principal axis
    else:
        u = np.array([1.0, 0.0])
    v = np.array([-u[1], u[0]])
    s, t = (pts - centre) @ u, (pts - centre) @ v
    n = max(int(np.ceil((np.ptp(t) + 1e-9) / stripe_m)), 1)
    first = t.min() + (np.ptp(t) - (n - 1) * stripe_m) / 2  # stripes centred on the footprint's width
    waypoints: list[np.ndarray] = []
    forward = True
    for k in range(n):
        tk = first + k * stripe_m
        sel = np.abs(t - tk) <= stripe_m / 2 + 1e-9
        if not sel.any():
            continue
        a, b = s[sel].min() - margin_m, s[sel].max() + margin_m
        ends = (a, b) if forward else (b, a)
        waypoints += [centre + e * u + tk * v for e in ends]
        forward = not forward
    return waypoints, float(np.arctan2(u[1], u[0]))
