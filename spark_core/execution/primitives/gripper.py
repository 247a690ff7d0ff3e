"""Closing and opening the gripper, with post-conditions from the width sensor and touch."""

from __future__ import annotations

import numpy as np

from ..protocols import ActionOutcome
from .base import Ctx, primitive


@primitive("grasp")
def grasp(ctx: Ctx) -> ActionOutcome:
    if (no := ctx.no_fingers()) is not None:
        return no
    g = ctx.world.kinematics[ctx.arm].robot.gripper
    ctx.memory.grasp_offset_xy_hand_m = np.zeros(2)  # unknown for a bare grasp: assume centred (pick sets it)
    ctx.world.set_gripper(ctx.arm, 0.0, ctx.args["force"], duration_s=0.4)
    width = ctx.world.gripper_width_m(ctx.arm)
    if width <= g.closed_empty_width_m or not ctx.world.pinched_bodies(ctx.arm):
        ctx.memory.held_label = None
        return ctx.fail(f"gripper closed on nothing: finger gap {width * 1000:.1f} mm, no object between the fingers")
    expected = ctx.args.get("target_width")
    if expected is not None and abs(width - expected) > max(0.015, 0.5 * expected):
        return ctx.fail(f"holding something {width * 1000:.0f} mm wide, expected about {expected * 1000:.0f} mm")
    return ActionOutcome.success(0.0, width_m=round(width, 4))


def open_gripper(ctx: Ctx) -> float:
    g = ctx.world.kinematics[ctx.arm].robot.gripper
    return ctx.world.set_gripper(ctx.arm, g.max_width_m, g.max_force_n / 2, duration_s=0.3)


@primitive("release")
def release(ctx: Ctx) -> ActionOutcome:
    if (no := ctx.no_fingers()) is not None:
        return no
    open_gripper(ctx)
    ctx.memory.held_label = None
    g = ctx.world.kinematics[ctx.arm].robot.gripper
    width = ctx.world.gripper_width_m(ctx.arm)
    if width < 0.8 * g.max_width_m:
        return ctx.fail(f"gripper did not open: finger gap {width * 1000:.1f} mm")
    if ctx.world.pinched_bodies(ctx.arm):
        return ctx.fail("object still stuck between the fingers after opening")
    return ActionOutcome.success(0.0)


@primitive("grasp_perturb")
def grasp_perturb(ctx: Ctx) -> ActionOutcome:
    """Open, then shift the hand sideways by a small random offset so the retried grasp closes elsewhere."""
    open_gripper(ctx)
    ang = ctx.rng.uniform(0, 2 * np.pi)
    d = ctx.args["offset"]
    return ctx.motion.move_line(
        ctx.tcp.translated([d * np.cos(ang), d * np.sin(ang), 0.0]), what="perturbed grasp pose"
    )
