"""Scene summary for the planner: labels, 3D keypoints, extents and geometric relations."""

from __future__ import annotations

from itertools import combinations, permutations

import numpy as np

from .keypoint import Keypoint

NEXT_TO_M = 0.15


def relations(kps: dict[str, Keypoint]) -> list[tuple[str, ...]]:
    """(relation, a, b[, c]) with relation in on, in, next_to, between, left_of; from keypoint geometry only."""
    out: list[tuple[str, ...]] = []
    for a, b in permutations(kps, 2):
        A, B = kps[a], kps[b]
        a_lo, b_hi = A.position_m[2] - A.extent_m[2] / 2, B.top_z_m
        b_half = B.extent_m[:2] / 2
        inside_xy = bool(np.all(np.abs(A.position_m[:2] - B.position_m[:2]) < b_half))
        if inside_xy and abs(a_lo - b_hi) < 0.015 and A.extent_m[2] > 0:
            out.append(("on", a, b))
        elif (
            inside_xy
            and a_lo < b_hi - 0.015
            and B.extent_m[2] > A.extent_m[2] * 0.5
            and a_lo >= B.position_m[2] - B.extent_m[2] / 2 - 0.01
        ):
            out.append(("in", a, b))
    for a, b in combinations(kps, 2):
        d = float(np.linalg.norm(kps[a].position_m[:2] - kps[b].position_m[:2]))
        if d < NEXT_TO_M and not any(r[0] in ("on", "in") and {r[1], r[2]} == {a, b} for r in out):
            out.append(("next_to", a, b))
    for a in kps:
        for b, c in combinations([k for k in kps if k != a], 2):
            p, q, r = kps[a].position_m[:2], kps[b].position_m[:2], kps[c].position_m[:2]
            seg = r - q
            t = float(np.dot(p - q, seg) / max(np.dot(seg, seg), 1e-9))
            if 0.2 < t < 0.8 and np.linalg.norm(q + t * seg - p) < 0.05:
                out.append(("between", a, b, c))
    return out


def summarise(kps: dict[str, Keypoint]) -> str:
    """Plain-text summary (world frame: x forward from the robot, y to its left, z up; metres)."""
    lines = ["objects (label: centre xyz m, size xyz m):"]
    for label, kp in kps.items():
        p, e = kp.position_m, kp.extent_m
        lines.append(f"- {label}: ({p[0]:.3f}, {p[1]:.3f}, {p[2]:.3f}), size ({e[0]:.3f}, {e[1]:.3f}, {e[2]:.3f})")
    rels = relations(kps)
    if rels:
        lines.append("relations:")
        for r in rels:
            lines.append(
                f"- {r[1]} is between {r[2]} and {r[3]}"
                if r[0] == "between"
                else f"- {r[1]} {r[0].replace('_', ' ')} {r[2]}"
            )
    return "\n".join(lines)
