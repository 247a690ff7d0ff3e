"""Serpentine coverage of a footprint by a tool of a given width."""

import numpy as np

from spark_core.execution.primitives.coverage import coverage_strokes


def _covered(points: np.ndarray, waypoints: list[np.ndarray], half_width: float) -> np.ndarray:
    """Whether each point lies within `half_width` of some segment between consecutive waypoints."""
    ok = np.zeros(len(points), bool)
    for a, b in zip(waypoints[:-1], waypoints[1:]):
        d = b - a
        s = np.clip(((points - a) @ d) / max(d @ d, 1e-12), 0, 1)
        ok |= np.linalg.norm(points - (a + s[:, None] * d), axis=1) <= half_width + 1e-9
    return ok


def test_a_random_trail_is_covered_by_strokes_as_wide_as_the_stripe():
    rng = np.random.default_rng(4)
    for _ in range(20):
        heading, p, pts = rng.uniform(-np.pi, np.pi), rng.uniform(-0.1, 0.1, 2), []
        for _ in range(100):  # robosuite Wipe's trail: 5 mm steps, the heading wandering
            heading += rng.normal(0, 0.5) if rng.uniform() > 0.7 else 0.0
            p = p + 0.005 * np.array([np.cos(heading), np.sin(heading)])
            pts.append(p)
        pts = np.array(pts)
        strokes, _ = coverage_strokes(pts, 0.09)
        assert _covered(pts, strokes, 0.045).all()


def test_strokes_run_along_the_principal_axis_and_skip_empty_stripes():
    line = np.array([[x, 0.3 * x] for x in np.linspace(0, 0.4, 40)])
    strokes, heading = coverage_strokes(line, 0.09)
    assert len(strokes) == 2  # one stroke along the whole line
    assert abs(np.sin(heading - np.arctan2(0.3, 1.0))) < 1e-6
    along = np.array([[x, 0.0] for x in np.linspace(0, 0.6, 60)])
    two = np.vstack([along, along + [0.0, 0.3]])  # two parallel lines with nothing between them
    strokes, heading = coverage_strokes(two, 0.09)
    assert _covered(two, strokes, 0.045).all()
    assert len(strokes) == 4 and abs(np.sin(heading)) < 1e-6  # two strokes along x; the 2 empty stripes skipped
    assert coverage_strokes(np.zeros((0, 2)), 0.09) == ([], 0.0)
