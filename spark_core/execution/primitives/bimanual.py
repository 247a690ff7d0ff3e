"""Two-arm skills: hand an object from one arm to the other, and lift one object with both arms; and the paper's
arm-routed pick and place (`pick_with_arm`, `place_with_arm`), which one arm of a two-arm robot runs in its branch.

Both are cooperative: the hands are meant to come close, so the shared-workspace clearance is lowered for
their duration. Simultaneous motions run on two threads (the world interleaves the arms' control steps)."""

from __future__ import annotations

import threading
from contextlib import contextmanager
from dataclasses import replace
from typing import cast

import numpy as np

from ...control.pose import Pose, rot_y, top_down_rotation, wrap_grasp_yaw
from ...perception import Keypoint
from ..protocols import ActionOutcome, FailureKind
from .base import Ctx, primitive
from .gripper import grasp, open_gripper
from .pick_place import grasp_object, lift_held, own_extent_xy, pick_and_lift, put_down, set_down_here

HANDOFF_HEIGHT_M = 0.25  # where the arms meet (TCP height above the table)
HANDOFF_GAP_M = 0.10  # TCP to TCP along the object at the meeting point: two hands side by side on one object
HANDOFF_MIN_GAP_M = 0.065  # closer, the two hands' bodies (6.4 cm thick along x) touch
HANDOFF_LEAN_RAD = 0.35  # each hand leans 20 deg away from the other: their wrists are wider than the hands
HANDOFF_GIVER_MARGIN_M = 0.02  # the giver's finger centres this far inside the end it takes
HANDOFF_END_MARGIN_M = 0.015  # finger centres this far inside an object's end (pads are 1.6 cm wide)
COOPERATIVE_CLEARANCE_M = 0.05


@contextmanager
def cooperative(*ctxs: Ctx):
    saved = [c.motion.clearance_m for c in ctxs]
    for c in ctxs:
        c.motion.clearance_m = COOPERATIVE_CLEARANCE_M
    try:
        yield
    finally:
        for c, s in zip(ctxs, saved):
            c.motion.clearance_m = s


def both(*steps) -> list[ActionOutcome]:
    """Run one step per arm at the same time; every step's outcome, in order."""
    out: list[ActionOutcome | None] = [None] * len(steps)

    def run(i, fn):
        try:
            out[i] = fn()
        except Exception as e:
            out[i] = ActionOutcome.fail(f"{type(e).__name__}: {e}", FailureKind.CONTROL)

    threads = [threading.Thread(target=run, args=(i, fn), daemon=True) for i, fn in enumerate(steps)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    return out  # type: ignore[return-value]


@primitive("pick_with_arm")
def pick_with_arm(ctx: Ctx) -> ActionOutcome:
    """Grasp with the plan's force limit (and expected width, when given; an angled approach when preferred), then
    lift."""
    a = ctx.args
    out = grasp_object(
        ctx,
        ctx.kp("keypoint_label"),
        force=a["force"],
        target_width=a.get("target_width"),
        angled=bool(a.get("prefer_angled")),
    )
    return lift_held(ctx, a["lift_height"]) if out.ok else out


@primitive("place_with_arm")
def place_with_arm(ctx: Ctx) -> ActionOutcome:
    """On the named target like `place`; with no target, straight down where the hand is (the paper's form)."""
    a = ctx.args
    tilt = float(a.get("tilt_angle") or 0.0)
    if a.get("target_label") is None:
        return set_down_here(ctx, tilt)
    return put_down(ctx, ctx.kp("target_label"), tilt_rad=tilt)


def _holds(ctx: Ctx, label: str) -> bool:
    return ctx.holding() and ctx.memory.held_label == label


@primitive("handoff")
def handoff(ctx: Ctx) -> ActionOutcome:
    """The giver holds the object (it picks it first if needed, just inside one end, so the receiver has room;
    see `_near_end`) and brings it between the arms, the rest of the object pointing at the receiver; the receiver
    grasps it beside the giver's hand, as far along as the object allows; only once the receiver holds it does the giver
    let go."""
    a = ctx.args
    label, giver, receiver = a["keypoint_label"], ctx.for_arm(a["from_arm"]), ctx.for_arm(a["to_arm"])
    if giver.arm == receiver.arm:
        return ctx.fail(f"handoff from the {giver.arm} arm to itself", FailureKind.PLANNER)
    base = {arm: ctx.world.kinematics[arm].T_world_base[:3, 3] for arm in (giver.arm, receiver.arm)}
    if not _holds(giver, label):
        kp = giver.kp("keypoint_label")
        out = pick_and_lift(giver, kp, 0.1, along_m=_near_end(giver, kp, base[giver.arm]))
        if not out.ok:
            return out
    toward = base[receiver.arm] - base[giver.arm]
    toward[2] = 0.0
    toward /= max(np.linalg.norm(toward), 1e-9)
    mid = (base[giver.arm] + base[receiver.arm]) / 2
    # Meet in front of arms standing side by side (their facing directions agree); between arms that face
    # each other across the table (the directions cancel), at the midpoint.
    facing = cast(
        np.ndarray, sum(ctx.world.kinematics[arm].T_world_base[:3, 0] for arm in (giver.arm, receiver.arm)) / 2
    )
    facing[2] = 0.0
    ahead = 0.5 * facing / np.linalg.norm(facing) if np.linalg.norm(facing) > 0.5 else np.zeros(3)
    meet = np.array([mid[0] + ahead[0], mid[1] + ahead[1], HANDOFF_HEIGHT_M])
    # The object lies along the giver's hand x axis, its centre `offset` along it from the TCP: turn the hand so
    # the longer part points at the receiver, who grips as far out as the object reaches (fingers inside its end).
    offset = float(giver.memory.grasp_offset_xy_hand_m[0])
    reach = abs(offset) + giver.memory.held_length_m / 2 - HANDOFF_END_MARGIN_M
    if reach < HANDOFF_MIN_GAP_M:
        return giver.fail(
            f"only {100 * (reach + HANDOFF_END_MARGIN_M):.1f} cm of the {label!r} sticks out of the "
            f"{giver.arm} hand: the other hand needs {100 * (HANDOFF_MIN_GAP_M + HANDOFF_END_MARGIN_M):.1f} cm "
            "beside it (grasp it nearer an end)",
            FailureKind.PLANNER,
        )
    gap = min(reach, HANDOFF_GAP_M)
    heading = float(np.arctan2(toward[1], toward[0])) + (np.pi if offset < 0 else 0.0)
    with cooperative(giver, receiver):
        open_gripper(receiver)
        out = giver.motion.move_to(_leaning(meet - toward * gap / 2, heading, toward, +1), what="hand-over point")
        if not out.ok:
            return out
        if not _holds(giver, label):
            return giver.fail(f"the {giver.arm} arm lost the {label!r} on the way to the hand-over point")
        grip = _leaning(giver.tcp.position_m + toward * gap, wrap_grasp_yaw(heading), toward, -1)  # where the giver is
        above = Pose(grip.position_m - 0.10 * grip.rotation[:, 2], grip.rotation)  # back along the fingers
        out = receiver.motion.move_to(above, what="above the hand-over grip")
        if out.ok:
            out = receiver.motion.move_line(grip, speed_m_s=0.15, what="hand-over grip")
        if not out.ok:
            return out
        receiver.args = {**receiver.args, "force": 40.0, "target_width": None}
        out = grasp(receiver)
        if not out.ok:  # the giver still holds it: nothing dropped
            open_gripper(receiver)
            return receiver.fail(f"the {receiver.arm} arm could not take the {label!r}: {out.reason}")
        receiver.memory.held_label = label
        receiver.memory.held_extent_m = giver.memory.held_extent_m
        receiver.memory.held_length_m = giver.memory.held_length_m
        receiver.memory.grasp_offset_z_m = giver.memory.grasp_offset_z_m
        open_gripper(giver)
        giver.memory.held_label = None
        giver.motion.move_line(giver.tcp.translated([0, 0, 0.08]), check=False)
    if not receiver.holding():
        return receiver.fail(f"the {label!r} slipped from the {receiver.arm} arm when the {giver.arm} arm let go")
    if giver.world.pinched_bodies(giver.arm):
        return giver.fail(f"the {giver.arm} arm still pinches something after opening")
    return ActionOutcome.success(0.0, receiver=receiver.arm, gap_m=round(gap, 3))


def _leaning(tcp_m: np.ndarray, yaw: float, toward: np.ndarray, sign: int) -> Pose:
    """A top-down pose turned HANDOFF_LEAN_RAD about the hand's y axis (the fingers' closing axis), fingers toward
    the receiver (sign +1, the giver) or away from the giver (sign -1, the receiver): the fingertips can be close on
    the object while the wrists and flanges, wider than the hands, lean apart."""
    R = top_down_rotation(yaw)
    phi = HANDOFF_LEAN_RAD * sign * (1.0 if float(np.dot(R[:, 0], toward)) > 0 else -1.0)
    return Pose(np.asarray(tcp_m, float), R @ rot_y(phi))


def _near_end(giver: Ctx, kp: Keypoint, giver_base: np.ndarray) -> float:
    """How far from the centre (along the grasp's hand x axis, m) the giver grasps: just inside one end, leaving
    the rest of the object to the receiver. The end toward the whole object when `kp` is a part of it (a hammer's
    handle: the end at the heavy head, so the load does not twist in the fingers), else the end on the giver's
    side. 0 for objects too short to matter."""
    half = float(max(own_extent_xy(kp))) / 2 - HANDOFF_GIVER_MARGIN_M
    if half <= 0:
        return 0.0
    yaw = giver.grasp_yaw(kp)
    axis = np.array([np.cos(yaw), np.sin(yaw)])
    toward = giver_base[:2] - kp.position_m[:2]
    whole = giver.whole_of(kp.label)
    if whole is not None and abs(float(np.dot(axis, whole.position_m[:2] - kp.position_m[:2]))) > 0.01:
        toward = whole.position_m[:2] - kp.position_m[:2]
    return half if float(np.dot(axis, toward)) > 0 else -half


def _handles(kp: Keypoint) -> list[Keypoint]:
    """The two ends of the object's long axis (its handles), as small keypoints whose short side runs along it."""
    yaw = kp.yaw_rad or 0.0
    own = kp.own_extent_xy_m
    # else, from the world-axis box: the object's own x axis is its long one if it lies along the longer side
    if own is not None:
        body_x_long = own[0] >= own[1]
        half = max(own[0], own[1]) / 2
    else:
        body_x_long = (kp.extent_m[0] >= kp.extent_m[1]) == (abs(np.cos(yaw)) >= abs(np.sin(yaw)))
        half = max(kp.extent_m[0], kp.extent_m[1]) / 2
    axis_yaw = yaw if body_x_long else yaw + np.pi / 2
    axis = np.array([np.cos(axis_yaw), np.sin(axis_yaw), 0.0])
    out = []
    for s in (-1.0, 1.0):
        p = kp.position_m + s * axis * (half - 0.012)
        out.append(
            replace(
                kp,
                label=f"{kp.label} handle",
                position_m=p,
                extent_m=np.array([0.024, 0.06, kp.extent_m[2]]),
                yaw_rad=axis_yaw,
                detail={},
            )
        )
    return out


@primitive("bimanual_lift")
def bimanual_lift(ctx: Ctx) -> ActionOutcome:
    """Each arm grasps the handle nearer to it, both at once; then both lift together."""
    kp = ctx.kp("keypoint_label")
    arms = [ctx.for_arm(a) for a in ctx.peers] if len(ctx.peers) >= 2 else []
    if len(arms) != 2:
        return ctx.fail("bimanual_lift needs an embodiment with two arms", FailureKind.PLANNER)
    handles = _handles(kp)
    bases = [ctx.world.kinematics[c.arm].T_world_base[:3, 3] for c in arms]
    if np.linalg.norm(handles[0].position_m - bases[0]) > np.linalg.norm(handles[1].position_m - bases[0]):
        handles = handles[::-1]
    grip_z = kp.top_z_m - 0.02
    with cooperative(*arms):
        outs = both(*(lambda c=c, h=h: grasp_object(c, h, force=60.0, z=grip_z) for c, h in zip(arms, handles)))
        failed = [o for o in outs if not o.ok]
        if failed:
            both(*(lambda c=c: (open_gripper(c), ActionOutcome.success(0.0))[1] for c in arms))
            return failed[0]
        z0 = kp.position_m[2]
        height = ctx.args["height"]
        both(
            *(
                lambda c=c: c.motion.move_line(c.tcp.translated([0, 0, height]), speed_m_s=0.08, check=False)
                for c in arms
            )
        )
    if not all(c.holding() for c in arms):
        return ctx.fail(f"the {kp.label!r} slipped from " + " and ".join(c.arm for c in arms if not c.holding()))
    now = ctx.observe(kp.label)
    raised = (now.position_m[2] - z0) if now is not None else min(c.tcp.position_m[2] for c in arms) - grip_z
    if raised < height / 2:
        return ctx.fail(f"the {kp.label!r} rose only {raised * 100:.1f} of {height * 100:.0f} cm")
    for c in arms:
        c.memory.held_label = kp.label
    return ActionOutcome.success(0.0, raised_m=round(float(raised), 4))
