"""Contact-rich motions along the table: push, sweep, wipe, constrained scrub."""

from __future__ import annotations

import numpy as np

from ...control.pose import wrap_grasp_yaw
from ..protocols import ActionOutcome, FailureKind
from .base import Ctx, primitive

DIRECTIONS = {"forward": (1.0, 0.0), "backward": (-1.0, 0.0), "left": (0.0, 1.0), "right": (0.0, -1.0)}


def _shove(ctx: Ctx, low: bool) -> ActionOutcome:
    kp = ctx.kp("keypoint_label")
    d = np.array(DIRECTIONS[ctx.args["direction"]])
    dist = ctx.args["distance"]
    half = float(np.max(np.abs(kp.extent_m[:2])) / 2)
    z = 0.015 if low else float(np.clip(kp.position_m[2], 0.015, 0.05))
    ctx.world.set_gripper(ctx.arm, 0.0, 40.0, duration_s=0.3)
    yaw = wrap_grasp_yaw(np.arctan2(d[1], d[0]))  # closing axis across the push: both fingers side by side
    start = np.array([*(kp.position_m[:2] - d * (half + 0.035)), z])
    before = kp.position_m.copy()
    out = ctx.motion.move_to([ctx.top_down(start + [0, 0, 0.1], yaw), ctx.top_down(start, yaw)],
                             what=f"point behind {kp.label!r}")
    if not out.ok:
        return out
    end = start + np.array([*(d * dist), 0.0])
    out = ctx.motion.move_line(ctx.top_down(end, yaw), speed_m_s=0.15, what="push end", check=False)
    lag = float(np.linalg.norm(ctx.tcp.position_m - end))
    ctx.motion.move_line(ctx.tcp.translated([0, 0, 0.1]), check=False)
    if lag > 0.03:  # pushing loads the arm, so allow more than the free-space 1 cm
        return ctx.fail(f"push stopped {lag * 100:.1f} cm short: blocked")
    after = ctx.observe(kp.label)
    if after is not None:
        moved = float(np.dot(after.position_m[:2] - before[:2], d))
        if after.position_m[2] > before[2] + 0.02:
            return ctx.fail(f"{kp.label!r} was lifted or tipped ({100 * (after.position_m[2] - before[2]):.1f} cm up) "
                            "instead of sliding")
        if moved < 0.5 * dist:
            return ctx.fail(f"{kp.label!r} moved {moved * 100:.1f} cm of {dist * 100:.0f} cm", FailureKind.CONTROL)
    return ActionOutcome.success(0.0)


@primitive("push_object")
def push_object(ctx: Ctx) -> ActionOutcome:
    return _shove(ctx, low=False)


@primitive("sweep")
def sweep(ctx: Ctx) -> ActionOutcome:
    return _shove(ctx, low=True)


def _surface_pattern(ctx: Ctx, label_slot: str, offsets: list[np.ndarray], press_m: float) -> ActionOutcome:
    """Bring the held tool down onto the target, then trace `offsets` (xy, m) pressing `press_m` below the
    contact height; success = in contact for most of the pattern."""
    target = ctx.kp(label_slot)
    if not ctx.holding():
        return ctx.fail("nothing held to scrub with")
    yaw = ctx.current_yaw()
    centre = target.position_m.copy()
    above = ctx.top_down([centre[0], centre[1], target.top_z_m + ctx.memory.grasp_offset_z_m + 0.05], yaw)
    out = ctx.motion.move_to(above, what=f"point above {target.label!r}")
    if not out.ok:
        return out
    out = ctx.motion.move_line(above.translated([0, 0, -0.1]), speed_m_s=0.04, stop=ctx.contact(), check=False)
    if not out.detail.get("stopped_early"):
        return ctx.fail(f"the tool never touched {target.label!r}", FailureKind.PERCEPTION)
    z = ctx.tcp.position_m[2] - press_m
    in_contact = 0
    for off in offsets:
        ctx.motion.move_line(ctx.top_down([centre[0] + off[0], centre[1] + off[1], z], yaw), speed_m_s=0.1, check=False)
        in_contact += ctx.world.wrist_force_n(ctx.arm) > 0.5
    ctx.motion.move_line(ctx.tcp.translated([0, 0, 0.08]), check=False)
    frac = in_contact / max(len(offsets), 1)
    if frac < 0.7:
        return ctx.fail(f"tool in contact for only {frac:.0%} of the pattern")
    return ActionOutcome.success(0.0, contact_fraction=round(frac, 3))


@primitive("constrained_scrub")
def constrained_scrub(ctx: Ctx) -> ActionOutcome:
    a = ctx.args
    r, n = a["scrub_radius_m"], a["n_cycles"]
    if a["pattern"] == "circle":
        ang = np.linspace(0, 2 * np.pi * n, 12 * n, endpoint=False)
        offs = [np.array([r * np.cos(t), r * np.sin(t)]) for t in ang]
    elif a["pattern"] == "zigzag":
        offs = [np.array([(-1) ** k * r, -r + 2 * r * k / (4 * n)]) for k in range(4 * n + 1)]
    else:
        offs = [np.array([(-1) ** k * r, 0.0]) for k in range(2 * n)]
    press = float(np.clip(a["force_n"] / 2500.0, 0.001, 0.01))  # position-controlled press depth ~ force / stiffness
    return _surface_pattern(ctx, "target_label", offs, press)


@primitive("wipe")
def wipe(ctx: Ctx) -> ActionOutcome:
    n = ctx.args["n_strokes"]
    offs = [np.array([0.0, (-1) ** k * 0.05]) for k in range(2 * n)]
    return _surface_pattern(ctx, "keypoint_label", offs, 0.004)
