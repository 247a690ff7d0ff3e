"""Pouring from a held container."""

from __future__ import annotations

import numpy as np

from ...control.ik import Unreachable
from ...control.pose import Pose, rot_y, rot_z, rotation_error
from ..protocols import ActionOutcome, FailureKind
from .base import Ctx, primitive

POUR_HEIGHT_M = 0.10  # TCP above the target's rim: low enough that beads land inside, high enough to clear it


@primitive("pour")
def pour(ctx: Ctx) -> ActionOutcome:
    """Carry the held container over the target, tilt it, hold, and return upright.

    The tilt axis is the one that swings the opening sideways: the approach axis for a side grasp (the palm
    stays clear of the opening), the finger axis for a top-down grasp. Of the two tilt directions the first
    whose upright and tilted poses both have IK solutions is used; the hand is placed so that the tilted
    opening sits over the target.
    """
    if not ctx.holding():
        return ctx.fail("pour with nothing in the gripper")
    target = ctx.kp("target_label")
    angle = ctx.args["pour_angle"]
    R = ctx.tcp.rotation
    side_grasp = abs(R[2, 2]) < 0.5
    tilt_axis = rot_z if side_grasp else rot_y
    up_in_tcp = R.T @ np.array([0.0, 0.0, 1.0])  # the container's opening direction, in the TCP frame
    lip = 0.05  # distance from the grasp point to the opening once tilted
    for sign in (1.0, -1.0):
        R_tilted = R @ tilt_axis(sign * angle)
        opening = R_tilted @ up_in_tcp
        flat = opening[:2] / max(np.linalg.norm(opening[:2]), 1e-6)
        pos = np.array([*(target.position_m[:2] - flat * lip), target.top_z_m + POUR_HEIGHT_M])
        upright, tilted = Pose(pos, R), Pose(pos, R_tilted)
        try:
            q_up = ctx.motion.ik(upright, what="pouring pose")
            ctx.motion.plan_line(tilted, q_up, upright, what="tilted pouring pose")
        except Unreachable:
            continue
        out = ctx.motion.move_to(upright, what=f"pouring pose over {target.label!r}")
        if not out.ok:
            return out
        out = ctx.motion.move_line(tilted, speed_m_s=0.05, what="pour tilt", check=False)
        if not out.ok:
            return out
        tilt_error = rotation_error(ctx.tcp.rotation, tilted.rotation)
        ctx.world.settle(1.0, ctx.arm)
        ctx.motion.move_line(upright, speed_m_s=0.05, check=False)
        if tilt_error > 0.3:
            return ctx.fail(
                f"wrist reached only {np.degrees(angle - tilt_error):.0f} of {np.degrees(angle):.0f} deg of tilt"
            )
        if not ctx.holding():
            return ctx.fail("dropped the container while pouring")
        return ActionOutcome.success(0.0, tilt_sign=sign)
    return ActionOutcome.fail(
        f"no reachable pouring pose over {target.label!r} in either tilt direction", FailureKind.KINEMATIC_LIMIT
    )
