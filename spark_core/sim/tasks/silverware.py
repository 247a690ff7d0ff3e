"""The bimanual silverware task of the SPARK paper's second example plan: a fork on the left, a knife on the
right, one tray in front; each arm puts its utensil in the tray (examples/plans/silverware_sort_bimanual.yaml)."""

from __future__ import annotations

from ..scene import ObjectRequest as O
from .builtin import inside
from .spec import TaskSpec

SUITE: dict[str, TaskSpec] = {
    t.name: t
    for t in [
        TaskSpec(
            "silverware_tray",
            "put the fork and the knife in the tray",
            (
                O("fork", "fork", "grey", x=(0.4, 0.45), y=(0.15, 0.2), yaw=(-0.2, 0.2)),
                O("knife", "knife", "grey", x=(0.4, 0.45), y=(-0.2, -0.15), yaw=(-0.2, 0.2)),
                O("tray", "tray", "white", x=(0.6, 0.62), y=(-0.01, 0.01)),
            ),
            lambda w: inside(w, "fork", "tray") and inside(w, "knife", "tray"),
            "fork and knife inside the tray's footprint, below its rim, released",
            max_sim_s=90.0,
            embodiments=("bimanual",),
        ),
    ]
}
