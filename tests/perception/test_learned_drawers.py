"""A drawer's mask kept to where a drawer can be (learned/drawers.py): below its cabinet's top, centred on its
handle across the front's width. Frames here are stand-ins whose every pixel has a chosen world point."""

from __future__ import annotations

import numpy as np

from spark_core.perception.learned.drawers import below_cabinet_top, centred_on_handle, front_width_axis


class PointFrame:
    """A frame whose pixel (v, u) sees world point points[v, u] (m); depth 1 m wherever a point is set. The
    camera stands at `eye` (m, world): by default beside the fronts below, which it sees edge-on."""

    def __init__(self, points: np.ndarray, eye: tuple[float, float, float] = (0.5, -1.0, 0.5)):
        self.points = points
        self.T_world_camera = np.eye(4)
        self.T_world_camera[:3, 3] = eye

    @property
    def depth_m(self) -> np.ndarray:
        return np.where(np.isfinite(self.points[..., 2]), 1.0, np.nan)

    def backproject(self, us: np.ndarray, vs: np.ndarray, z: np.ndarray) -> np.ndarray:
        return self.points[vs.astype(int), us.astype(int)]


def _frame(h: int = 60, w: int = 80) -> PointFrame:
    return PointFrame(np.full((h, w, 3), np.nan))


def test_drawer_pixels_on_the_cabinet_top_are_the_cabinets():
    f = _frame()
    cabinet = np.zeros((60, 80), bool)
    cabinet[0:30, :] = True
    f.points[0:30, :] = [0.5, 0.0, 0.17]  # the cabinet's top face, 17 cm up
    drawer = np.zeros((60, 80), bool)
    drawer[25:55, 10:70] = True
    f.points[30:55, 10:70] = [0.4, 0.0, 0.11]  # the open drawer's rim, 11 cm up; rows 25-29 lie on the top face
    kept = below_cabinet_top(drawer, [cabinet], f)  # type: ignore[arg-type]
    assert not kept[25:30].any() and kept[30:55, 10:70].all()
    # no touching cabinet, or nothing left below its top: the mask is kept as it is
    assert (below_cabinet_top(drawer, [], f) == drawer).all()  # type: ignore[arg-type]
    assert (below_cabinet_top(drawer & cabinet, [cabinet], f) == (drawer & cabinet)).all()  # type: ignore[arg-type]


def _front(f: PointFrame, y0: float, y1: float) -> np.ndarray:
    """A closed drawer's front: a vertical face at x = 0.5 m from y0 to y1 (m), 3-11 cm up, one pixel column per
    0.5 cm of y."""
    mask = np.zeros(f.depth_m.shape, bool)
    ys = np.arange(y0, y1, 0.005)
    for u, y in enumerate(ys):
        for v, z in enumerate(np.linspace(0.03, 0.11, 20)):
            f.points[v, u] = [0.5, y, z]
            mask[v, u] = True
    return mask


def test_a_lying_handle_centres_the_front_along_its_length():
    f = _frame(60, 120)
    drawer = _front(f, 0.06, 0.36)  # the true front spans y 0.06-0.30; 6 cm of cabinet face taken on one side
    handle = np.zeros_like(drawer)
    for u, y in enumerate(np.arange(0.13, 0.23, 0.005)):  # a 10 cm bar along the front, centred at y = 0.18
        for v, x in enumerate((0.47, 0.475)):
            f.points[40 + v, 80 + u] = [x, y, 0.08]
            handle[40 + v, 80 + u] = True
    assert abs(abs(front_width_axis(f.points[handle])[1]) - 1.0) < 1e-6  # type: ignore[index]
    kept = centred_on_handle(drawer, handle, f)  # type: ignore[arg-type]
    ys = f.points[kept][:, 1]
    assert abs((ys.min() + ys.max()) / 2 - 0.18) < 0.01 and ys.max() < 0.31
    # seen squarely (the camera in front of it), the mask's own ends are trusted
    f.T_world_camera[:3, 3] = (-1.0, 0.18, 0.5)
    assert (centred_on_handle(drawer, handle, f) == drawer).all()  # type: ignore[arg-type]


def test_a_standing_handle_stands_off_the_front_so_the_width_is_across_that():
    f = _frame(60, 120)
    drawer = _front(f, 0.08, 0.36)  # centre of the true front y = 0.18: it reaches 10 cm left, 18 cm right
    handle = np.zeros_like(drawer)
    for v, z in enumerate(np.linspace(0.05, 0.12, 15)):  # a 7 cm tall bar standing 4 cm off the front at y 0.18
        for u, x in enumerate(np.linspace(0.46, 0.50, 8)):
            f.points[40 + v % 15, 90 + u + 10 * (v // 15)] = [x, 0.18 + 0.002 * (u % 2), z]
            handle[40 + v % 15, 90 + u + 10 * (v // 15)] = True
    axis = front_width_axis(f.points[handle])
    assert axis is not None and abs(abs(axis[1]) - 1.0) < 0.05  # across the 4 cm standoff (x), i.e. along y
    kept = centred_on_handle(drawer, handle, f)  # type: ignore[arg-type]
    ys = f.points[kept][:, 1]
    assert abs((ys.min() + ys.max()) / 2 - 0.18) < 0.01


def test_a_handle_without_a_long_axis_leaves_the_mask_alone():
    f = _frame(60, 120)
    drawer = _front(f, 0.0, 0.3)
    handle = np.zeros_like(drawer)
    for v in range(5):
        for u in range(5):  # a round knob: no long axis in xy
            f.points[40 + v, 90 + u] = [0.48 + 0.004 * v, 0.15 + 0.004 * u, 0.08]
            handle[40 + v, 90 + u] = True
    assert front_width_axis(f.points[handle]) is None
    assert (centred_on_handle(drawer, handle, f) == drawer).all()  # type: ignore[arg-type]


def test_an_open_drawer_reaching_back_from_its_front_is_not_cut():
    """Seen edge-on, an open drawer's side wall reaches back from the front and hides the front's far end: the
    mask's ends are then not spills, and the mask is kept."""
    f = _frame(60, 120)
    drawer = _front(f, 0.06, 0.36)
    for u, x in enumerate(np.arange(0.40, 0.50, 0.005)):  # the near side wall, 10 cm deep, at y = 0.06
        for v, z in enumerate(np.linspace(0.03, 0.11, 20)):
            f.points[30 + v, 80 + u] = [x, 0.06, z]
            drawer[30 + v, 80 + u] = True
    handle = np.zeros_like(drawer)
    for u, y in enumerate(np.arange(0.13, 0.23, 0.005)):
        for v, x in enumerate((0.47, 0.475)):
            f.points[55 + v, 90 + u] = [x, y, 0.08]
            handle[55 + v, 90 + u] = True
    assert (centred_on_handle(drawer, handle, f) == drawer).all()  # type: ignore[arg-type]
