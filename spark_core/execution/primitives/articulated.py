"""Articulated objects and in-hand rotations: drawers, knobs, pulling, pressing, screwing."""

from __future__ import annotations

import numpy as np

from ...control.pose import Pose, rot_z
from ..protocols import ActionOutcome, FailureKind
from .base import Ctx, primitive
from .gripper import grasp, open_gripper
from .pick_place import SIDE_ROTATION, grasp_object


def _grasp_handle(ctx: Ctx, label_slot: str = "keypoint_label") -> ActionOutcome:
    """Horizontal approach toward +x (handles face the robot), fingers closing vertically around the bar."""
    kp = ctx.kp(label_slot)
    at = kp.position_m.copy()
    at[0] -= kp.extent_m[0] / 2 - 0.01  # finger pads 1 cm behind the handle's front face, around the grip
    open_gripper(ctx)
    # A big wrist reorientation (e.g. the UR10 turning from top-down to sideways) happens above and in front of
    # the handle, in free space, then the hand descends to the approach point.
    out = ctx.motion.move_to(Pose(at - [0.06, 0, 0], SIDE_ROTATION), what=f"approach to {kp.label!r}",
                             reconfigure_via=np.array([-0.08, 0.0, 0.15]))
    if not out.ok:
        return out
    out = ctx.motion.move_line(Pose(at, SIDE_ROTATION), speed_m_s=0.15, what=f"{kp.label!r}",
                               stop=ctx.contact(15.0), check=False)
    ctx.args = {**ctx.args, "force": 60.0, "target_width": None}
    return grasp(ctx)


def _pull_held(ctx: Ctx, distance: float, what: str) -> ActionOutcome:
    """Pull toward the robot (-x) while holding; success = the hand travelled with the handle still pinched."""
    start = ctx.tcp.position_m.copy()
    ctx.motion.move_line(Pose(start - [distance, 0, 0], SIDE_ROTATION), speed_m_s=0.2, check=False)
    travelled = float(start[0] - ctx.tcp.position_m[0])
    held = ctx.holding()
    open_gripper(ctx)
    # back and up, clear of the drawer: the next (often joint-space) move must not sweep the hand through it
    ctx.motion.move_line(Pose(ctx.tcp.position_m + [-0.06, 0, 0.08], SIDE_ROTATION), speed_m_s=0.4, check=False)
    if not held:
        return ctx.fail(f"the {what} slipped out of the gripper while pulling")
    if travelled < 0.8 * distance:
        return ctx.fail(f"the {what} moved only {travelled * 100:.1f} of {distance * 100:.0f} cm: blocked")
    return ActionOutcome.success(0.0, travelled_m=round(travelled, 4))


@primitive("open_drawer")
@primitive("pull")
def pull(ctx: Ctx) -> ActionOutcome:
    """Grasp the handle at the keypoint and pull it toward the robot (a drawer is opened the same way)."""
    out = _grasp_handle(ctx)
    if not out.ok:
        return out
    return _pull_held(ctx, ctx.args["distance"], "drawer" if "drawer" in ctx.args["keypoint_label"] else "handle")


@primitive("close_drawer")
def close_drawer(ctx: Ctx) -> ActionOutcome:
    """Push the drawer front with open fingers (the handle passes between them, so nothing hooks it on the way
    back) until the drawer sits on its end stop (sustained force)."""
    kp = ctx.kp("keypoint_label")
    open_gripper(ctx)
    at = kp.position_m.copy()
    out = ctx.motion.move_to(Pose(at - [0.08, 0, 0], SIDE_ROTATION), what=f"approach to {kp.label!r}")
    if not out.ok:
        return out
    out = ctx.motion.move_line(Pose(at + [0.30, 0, 0], SIDE_ROTATION), speed_m_s=0.15,
                               stop=ctx.sustained_contact(25.0, ticks=5), check=False)
    ctx.motion.move_line(Pose(ctx.tcp.position_m - [0.08, 0, 0], SIDE_ROTATION), check=False)
    if not out.detail.get("stopped_early"):
        return ctx.fail("pushed 30 cm without reaching the drawer's end stop: the drawer is not where expected",
                        FailureKind.PERCEPTION)
    return ActionOutcome.success(0.0)


def _rotate_held(ctx: Ctx, angle_rad: float) -> ActionOutcome:
    tcp = ctx.tcp
    out = ctx.motion.move_line(Pose(tcp.position_m, rot_z(angle_rad) @ tcp.rotation), speed_m_s=0.05, what="rotated grip",
                               check=False)
    rel = tcp.rotation.T @ ctx.tcp.rotation  # measured on the TCP, not on a joint: any wrist layout
    turned = abs(float(np.arctan2(rel[1, 0], rel[0, 0])))
    if not ctx.holding():
        return ctx.fail("lost the grip while turning")
    if turned < 0.5 * abs(angle_rad):
        return ctx.fail(f"turned only {np.degrees(turned):.0f} of {np.degrees(abs(angle_rad)):.0f} deg: blocked")
    return out


@primitive("turn_knob")
def turn_knob(ctx: Ctx) -> ActionOutcome:
    kp = ctx.kp("keypoint_label")
    out = grasp_object(ctx, kp, force=30.0, z=kp.top_z_m - 0.012)  # knobs are gripped by the fin on top
    if not out.ok:
        return out
    out = _rotate_held(ctx, np.radians(ctx.args["angle"]))
    open_gripper(ctx)
    ctx.memory.held_label = None
    ctx.motion.move_line(ctx.tcp.translated([0, 0, 0.08]), check=False)
    return out


@primitive("screw")
def screw(ctx: Ctx) -> ActionOutcome:
    if not ctx.holding():
        out = grasp_object(ctx, ctx.kp("keypoint_label"), force=40.0)
        if not out.ok:
            return out
    return _rotate_held(ctx, np.radians(ctx.args["angle"]))


@primitive("press")
def press(ctx: Ctx) -> ActionOutcome:
    kp = ctx.kp("keypoint_label")
    ctx.world.set_gripper(ctx.arm, 0.0, 40.0, duration_s=0.3)
    above = ctx.top_down([kp.position_m[0], kp.position_m[1], kp.top_z_m + 0.08])
    out = ctx.motion.move_to(above, what=f"point above {kp.label!r}")
    if not out.ok:
        return out
    out = ctx.motion.move_line(above.translated([0, 0, -0.12]), speed_m_s=0.04, stop=ctx.contact(ctx.args["force_n"]), check=False)
    ctx.motion.move_line(ctx.tcp.translated([0, 0, 0.06]), check=False)
    if not out.detail.get("stopped_early"):
        return ctx.fail(f"no contact reached at {kp.label!r}", FailureKind.PERCEPTION)
    return ActionOutcome.success(0.0)
