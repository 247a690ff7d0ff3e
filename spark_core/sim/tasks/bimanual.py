"""The `bimanual` task suite: tasks that need (or benefit from) two arms, on the two-Panda cell."""

from __future__ import annotations

import numpy as np

from ..scene import ObjectRequest as O
from ..world import MujocoWorld
from .builtin import _pos, inside
from .spec import TaskSpec

ALONG_Y = (np.pi / 2 - 0.05, np.pi / 2 + 0.05)  # long axis across the table: one end toward each arm


def _held_by(w: MujocoWorld, body: str) -> set[str]:
    return {a for a in w.arms if w.body_id(body) in w.pinched_bodies(a)}


def _tray_lifted(w: MujocoWorld) -> bool:
    lo, hi = w.body_aabb("green tray")
    level = abs(lo[2] - (hi[2] - 0.06)) < 0.03  # bottom and top still one tray-height apart: not tipped
    return bool(lo[2] > 0.06 and _held_by(w, "green tray") == set(w.arms) and level)


def _handed_over(w: MujocoWorld) -> bool:
    return bool(_pos(w, "red bar")[2] > 0.08 and _held_by(w, "red bar") == {"left"})


SUITE: dict[str, TaskSpec] = {
    t.name: t
    for t in [
        TaskSpec(
            "lift_tray",
            "lift the green serving tray with both hands",
            (O("green tray", "carry_tray", "green", x=(0.5, 0.55), y=(-0.02, 0.02), yaw=ALONG_Y),),
            _tray_lifted,
            "tray bottom > 6 cm above the table, level, held by both arms",
            embodiments=("bimanual",),
        ),
        TaskSpec(
            "handover_bar",
            "pick up the red bar with the right arm and hand it to the left arm",
            (O("red bar", "bar", "red", x=(0.45, 0.55), y=(-0.22, -0.16), yaw=(-0.3, 0.3)),),
            _handed_over,
            "red bar held by the left arm only, > 8 cm above the table",
            embodiments=("bimanual",),
        ),
        TaskSpec(
            "sort_bimanual",
            "put the red block in the red tray and the blue block in the blue tray",
            (
                O("red block", "block", "red", x=(0.42, 0.52), y=(0.12, 0.2)),
                O("blue block", "block", "blue", x=(0.42, 0.52), y=(-0.2, -0.12)),
                O("red tray", "tray", "red", x=(0.55, 0.62), y=(0.3, 0.36)),
                O("blue tray", "tray", "blue", x=(0.55, 0.62), y=(-0.36, -0.3)),
            ),
            lambda w: inside(w, "red block", "red tray") and inside(w, "blue block", "blue tray"),
            "red block in the red tray and blue block in the blue tray, released",
            embodiments=("bimanual",),
        ),
    ]
}
