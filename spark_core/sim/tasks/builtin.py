"""The `builtin` task suite: tabletop tasks with success predicates over simulator state."""

from __future__ import annotations

from typing import Any

import numpy as np

from ..scene import ObjectRequest as O
from ..world import MujocoWorld
from .spec import TaskSpec

FREE: dict[str, Any] = dict(x=(0.38, 0.62), y=(-0.25, 0.25))


def _pos(w: MujocoWorld, body: str) -> np.ndarray:
    lo, hi = w.body_aabb(body)
    return np.array([(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, lo[2]])  # footprint centre, bottom z


def _released(w: MujocoWorld, body: str) -> bool:
    return not any(w.body_id(body) in w.pinched_bodies(a) for a in w.arms)


def on_top(w: MujocoWorld, obj: str, support: str, xy_tol: float) -> bool:
    p, s = _pos(w, obj), w.body_aabb(support)
    centre = (s[0][:2] + s[1][:2]) / 2
    return bool(np.linalg.norm(p[:2] - centre) < xy_tol and abs(p[2] - s[1][2]) < 0.015 and _released(w, obj))


def inside(w: MujocoWorld, obj: str, container: str, margin: float = 0.0) -> bool:
    p, (lo, hi) = _pos(w, obj), w.body_aabb(container)
    return bool(
        np.all(p[:2] > lo[:2] + margin) and np.all(p[:2] < hi[:2] - margin) and p[2] < hi[2] and _released(w, obj)
    )


def _lifted(w):
    return bool(_pos(w, "red block")[2] > 0.05 and not _released(w, "red block"))


def _open_drawer(w: MujocoWorld, rng) -> None:
    w.set_joint_value("cabinet/drawer_slide", 0.15)


def _fill_mug(w: MujocoWorld, rng) -> None:
    base = w.body_position("mug")
    for k in range(BEADS):
        off = rng.uniform(-0.008, 0.008, 2)
        w.set_body_position(f"bead {k}", [base[0] + off[0], base[1] + off[1], base[2] + 0.012 + 0.016 * k])


BEADS = 5


def _poured(w):
    n = 0
    for k in range(BEADS):
        p, (lo, hi) = w.body_position(f"bead {k}"), w.body_aabb("bowl")
        n += bool(np.all(p[:2] > lo[:2]) and np.all(p[:2] < hi[:2]) and p[2] < hi[2])
    return n >= 3


class _Coverage:
    """Scrub coverage: 2 cm cells of the plate the sponge touched (sampled every control period)."""

    CELL_M, NEEDED = 0.02, 6

    def __init__(self):
        self.cells: set[tuple[int, int]] = set()

    def __call__(self, w: MujocoWorld) -> None:
        if w.bodies_in_contact("sponge", "plate"):
            rel = w.body_position("sponge")[:2] - w.body_position("plate")[:2]
            self.cells.add(tuple(np.floor(rel / self.CELL_M).astype(int)))


def _scrub_setup(w: MujocoWorld, rng) -> None:
    cov = _Coverage()
    w.monitors.append(cov)
    w.scene.extra["coverage"] = cov


def _scrubbed(w):
    return len(w.scene.extra["coverage"].cells) >= _Coverage.NEEDED


CABINET = O("cabinet", "cabinet", "brown", (0.74, 0.78), (0.18, 0.26))
STOVE = O("stove", "stove", "grey", (0.56, 0.62), (-0.1, 0.1))

SUITE: dict[str, TaskSpec] = {
    t.name: t
    for t in [
        TaskSpec(
            "lift_block",
            "pick up the red block",
            (O("red block", "block", "red", **FREE), O("blue block", "block", "blue", **FREE)),
            _lifted,
            "red block bottom > 5 cm above the table and held",
        ),
        TaskSpec(
            "block_on_plate",
            "put the red block on the plate",
            (O("red block", "block", "red", **FREE), O("plate", "plate", "white", **FREE)),
            lambda w: on_top(w, "red block", "plate", 0.07),
            "red block resting on the plate, within 7 cm of its centre, released",
        ),
        TaskSpec(
            "block_in_bowl",
            "put the red block in the bowl",
            (O("red block", "block", "red", **FREE), O("bowl", "bowl", "white", **FREE)),
            lambda w: inside(w, "red block", "bowl", 0.01),
            "red block inside the bowl's footprint, below its rim, released",
        ),
        TaskSpec(
            "block_in_basket",
            "put the green block in the basket",
            (O("green block", "block", "green", **FREE), O("basket", "basket", "brown", **FREE)),
            lambda w: inside(w, "green block", "basket", 0.01),
            "green block inside the basket, released",
        ),
        TaskSpec(
            "stack_two",
            "stack the red block on the blue block",
            (O("red block", "block", "red", **FREE), O("blue block", "block", "blue", **FREE)),
            lambda w: on_top(w, "red block", "blue block", 0.02),
            "red block on the blue block (xy < 2 cm), released",
        ),
        TaskSpec(
            "stack_three",
            "stack the green block on the blue block, then the red block on the green block",
            (
                O("red block", "block", "red", **FREE),
                O("green block", "block", "green", **FREE),
                O("blue block", "block", "blue", **FREE),
            ),
            lambda w: on_top(w, "green block", "blue block", 0.02) and on_top(w, "red block", "green block", 0.02),
            "green on blue and red on green (xy < 2 cm each), released",
        ),
        TaskSpec(
            "push_to_zone",
            "push the red block forward into the green area",
            (
                O("red block", "block", "red", x=(0.38, 0.45), y=(-0.15, 0.15)),
                O("green area", "zone", "green", x=(0.17, 0.19), y=(-0.02, 0.02), near="red block"),
            ),
            lambda w: inside(w, "red block", "green area"),
            "red block centre inside the green square",
        ),
        TaskSpec(
            "open_drawer",
            "open the drawer of the cabinet",
            (CABINET, O("red block", "block", "red", x=(0.38, 0.55), y=(-0.25, 0.0))),
            lambda w: w.joint_value("cabinet/drawer_slide") > 0.10,
            "drawer slide > 10 cm",
        ),
        TaskSpec(
            "close_drawer",
            "close the drawer of the cabinet",
            (CABINET, O("red block", "block", "red", x=(0.38, 0.55), y=(-0.25, 0.0))),
            lambda w: w.joint_value("cabinet/drawer_slide") < 0.02,
            "drawer slide < 2 cm",
            setup=_open_drawer,
        ),
        TaskSpec(
            "block_in_drawer",
            "open the drawer and put the red block inside it",
            (CABINET, O("red block", "block", "red", x=(0.38, 0.55), y=(-0.25, 0.0))),
            lambda w: inside(w, "red block", "cabinet/drawer"),
            "red block inside the drawer's footprint, released",
            max_sim_s=80.0,
        ),
        TaskSpec(
            "turn_on_stove",
            "turn on the stove",
            (STOVE, O("red block", "block", "red", x=(0.38, 0.5), y=(-0.3, 0.3))),
            lambda w: w.joint_value("stove/knob_hinge") > np.radians(60),
            "knob turned > 60 deg",
        ),
        TaskSpec(
            "pour_beads",
            "pour the beads from the mug into the bowl",
            (
                O("mug", "mug", "red", x=(0.42, 0.5), y=(-0.2, -0.05)),
                O("bowl", "bowl", "white", x=(0.45, 0.6), y=(0.08, 0.25)),
                *[
                    O(f"bead {k}", "ball", "yellow", x=(0.0, 0.0), y=(0.0, 0.0), z=0.02 + 0.016 * k, near="mug")
                    for k in range(BEADS)
                ],
            ),
            _poured,
            "at least 3 of 5 beads inside the bowl",
            setup=_fill_mug,
        ),
        TaskSpec(
            "scrub_plate",
            "scrub the plate with the sponge",
            (O("sponge", "sponge", "yellow", **FREE), O("plate", "plate", "white", **FREE)),
            _scrubbed,
            f"sponge touched >= {_Coverage.NEEDED} distinct 2 cm cells of the plate",
            setup=_scrub_setup,
        ),
        TaskSpec(
            "sort_two",
            "put the red block in the green tray and the blue block in the yellow tray",
            (
                O("red block", "block", "red", x=(0.4, 0.55), y=(-0.1, 0.1)),
                O("blue block", "block", "blue", x=(0.4, 0.55), y=(-0.1, 0.1)),
                O("green tray", "tray", "green", x=(0.45, 0.55), y=(0.3, 0.34)),
                O("yellow tray", "tray", "yellow", x=(0.45, 0.55), y=(-0.34, -0.3)),
            ),
            lambda w: inside(w, "red block", "green tray") and inside(w, "blue block", "yellow tray"),
            "red block in the green tray and blue block in the yellow tray, released",
        ),
    ]
}
