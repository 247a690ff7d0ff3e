"""Grasping objects and putting them down: pick, place, place_in, stack, insert, place_over, drag, hang, grasp_se3."""

from __future__ import annotations

import numpy as np

from ...control.pose import Pose, rot_y, wrap_grasp_yaw
from ...perception import Keypoint
from ..protocols import ActionOutcome, FailureKind
from .base import CONTACT_FORCE_N, TABLE_CLEARANCE_M, Ctx, primitive
from .gripper import grasp, open_gripper

APPROACH_M = 0.10
ANGLED_LEAN_RAD = 0.5  # an angled grasp leans this far from vertical (about the fingers' closing axis)
RIM_PRESHAPE_M = 0.04  # finger gap when going down over a rim
SUPPORT_TOL_M = 0.012  # how far below the expected support height contact may come before the target is "gone"
# Horizontal approach: TCP z = world +x, fingers close along world y (the hand's wide side stays horizontal,
# clear of the table).
SIDE_ROTATION = np.array([[0.0, 0.0, 1.0], [0.0, 1.0, 0.0], [-1.0, 0.0, 0.0]])


def _seq(*steps) -> ActionOutcome:
    for step in steps:
        out = step()
        if not out.ok:
            return out
    return ActionOutcome.success(0.0)


def grasp_object(
    ctx: Ctx,
    kp: Keypoint,
    force: float = 50.0,
    strategy: str = "top_down",
    target_width: float | None = None,
    z: float | None = None,
    along_m: float = 0.0,
    angled: bool = False,
) -> ActionOutcome:
    """Approach from above (or from the robot's side), descend straight, close, and remember what is held.
    `along_m`: grasp that far from the centre along the object's long axis (a top-down grasp's hand x axis).
    `angled`: a top-down grasp leans ANGLED_LEAN_RAD about the fingers' closing axis, fingertips pointing away from
    the arm's base, and comes in along the fingers (reaches under an overhang, rests on less of the table)."""
    open_gripper(ctx)
    if strategy == "side":
        z = float(max(kp.position_m[2] + 0.01, 0.04))  # keep the hand's lower edge off the table
        at = np.array([kp.position_m[0], kp.position_m[1], z])
        pre, pose = Pose(at - [APPROACH_M, 0, 0], SIDE_ROTATION), Pose(at, SIDE_ROTATION)
    else:
        yaw = ctx.grasp_yaw(kp)
        at = kp.position_m[:2] + along_m * np.array([np.cos(yaw), np.sin(yaw)])
        z = ctx.grasp_height(kp) if z is None else z
        rim = _rim_grasp(ctx, kp) if target_width is None else None
        if rim is not None:  # too wide for the fingers to span: take its rim (a bowl's wall, a plate's edge)
            at, yaw, z = rim
            # pre-shape half open, so the inner finger goes down beside the wall, not into the bowl's floor
            ctx.world.set_gripper(ctx.arm, RIM_PRESHAPE_M, 20.0, duration_s=0.1)
        pre = ctx.top_down([at[0], at[1], kp.top_z_m + APPROACH_M], yaw)
        pose = ctx.top_down([at[0], at[1], z], yaw)
        if angled:
            pose = _leaned(ctx, pose)
            pre = Pose(pose.position_m - APPROACH_M * pose.rotation[:, 2], pose.rotation)  # back along the fingers
    out = _seq(
        lambda: ctx.motion.move_to(pre, what=f"approach above {kp.label!r}"),
        lambda: ctx.motion.move_line(pose, speed_m_s=0.2, what=f"grasp pose of {kp.label!r}"),
    )
    if not out.ok:
        return out
    ctx.args = {**ctx.args, "force": force, "target_width": target_width}
    out = grasp(ctx)
    if out.ok:
        ctx.memory.held_label = kp.label
        ctx.memory.held_extent_m = np.asarray(kp.extent_m, float).copy()
        ctx.memory.held_length_m = float(max(own_extent_xy(kp)))
        ctx.memory.grasp_offset_z_m = float(pose.position_m[2] - (kp.position_m[2] - kp.extent_m[2] / 2))
        ctx.memory.grasp_offset_xy_hand_m = _rot2(-_hand_yaw(pose.rotation)) @ (kp.position_m[:2] - pose.position_m[:2])
    return out


def _leaned(ctx: Ctx, pose: Pose) -> Pose:
    """`pose` leaned ANGLED_LEAN_RAD about the hand's y axis (the fingers' closing axis), the fingertips (hand z)
    pointing away from the arm's base; raised by what the pads' lower corners drop."""
    base = ctx.world.kinematics[ctx.arm].T_world_base[:2, 3]
    out = pose.position_m[:2] - base
    R = max(
        (pose.rotation @ rot_y(s * ANGLED_LEAN_RAD) for s in (1.0, -1.0)),
        key=lambda r: float(np.dot(r[:2, 2], out)),
    )
    lift = 0.01 * np.sin(ANGLED_LEAN_RAD)
    return Pose(pose.position_m + [0.0, 0.0, lift], R)


def own_extent_xy(kp: Keypoint):
    """The object's own length and width when known, else its world box."""
    return kp.own_extent_xy_m or kp.extent_m[:2]


def _hand_yaw(rotation: np.ndarray) -> float:
    """Direction of the hand's x axis about world z (not wrapped: a half turn moves an off-centre object)."""
    return float(np.arctan2(rotation[1, 0], rotation[0, 0]))


def _rot2(angle: float) -> np.ndarray:
    c, s = np.cos(angle), np.sin(angle)
    return np.array([[c, -s], [s, c]])


def _rim_grasp(ctx: Ctx, kp: Keypoint) -> tuple[np.ndarray, float, float] | None:
    """For an object wider than the open fingers in every direction: (xy, yaw, z) of a grasp on its edge nearest
    the robot, fingers closing radially across the wall, 2 cm below the top. None when the fingers can span it."""
    g = ctx.world.kinematics[ctx.arm].robot.gripper
    own = own_extent_xy(kp)
    if min(own[0], own[1]) < 0.9 * g.max_width_m:
        return None
    base = ctx.world.kinematics[ctx.arm].T_world_base[:2, 3]
    radial = base - kp.position_m[:2]
    radial = radial / max(float(np.linalg.norm(radial)), 1e-9)
    half = min(float(kp.extent_m[0]), float(kp.extent_m[1])) / 2
    xy = kp.position_m[:2] + radial * max(half - 0.012, 0.0)
    yaw = wrap_grasp_yaw(float(np.arctan2(radial[1], radial[0])) - np.pi / 2)  # closing axis along the radius
    z = max(kp.top_z_m - 0.02, TABLE_CLEARANCE_M)
    return xy, yaw, z


def lift_held(ctx: Ctx, height: float) -> ActionOutcome:
    out = ctx.motion.move_line(ctx.tcp.translated([0, 0, height]), speed_m_s=0.12, what="lift height", check=False)
    if not ctx.holding():
        ctx.memory.held_label = None
        return ctx.fail("object slipped out of the gripper while lifting")
    return out


@primitive("grasp_se3")
def grasp_se3(ctx: Ctx) -> ActionOutcome:
    a = ctx.args
    return grasp_object(ctx, ctx.kp("keypoint_label"), a["force"], a["strategy"], a.get("target_width"))


def pick_and_lift(ctx: Ctx, kp: Keypoint, height: float, along_m: float = 0.0) -> ActionOutcome:
    out = grasp_object(ctx, kp, along_m=along_m)
    return lift_held(ctx, height) if out.ok else out


@primitive("pick")
def pick(ctx: Ctx) -> ActionOutcome:
    return pick_and_lift(ctx, ctx.kp("keypoint_label"), ctx.args["lift_height"])


def put_down(
    ctx: Ctx,
    target: Keypoint,
    offset_xy=(0.0, 0.0),
    floor_z: float | None = None,
    what: str = "target",
    tilt_rad: float = 0.0,
) -> ActionOutcome:
    """Carry the held object above `target`, descend until the wrist feels support, release, retract.

    The expected support height is the target's top (or `floor_z` inside a container). Descending well past
    it without feeling anything means the target is not where perception said: fail instead of dropping.
    `tilt_rad`: above the target, tilt the held object about the fingers' closing axis before the descent.
    """
    if not ctx.holding():
        return ctx.fail(f"nothing in the gripper to put on the {what}")
    support_z = target.top_z_m if floor_z is None else floor_z
    tcp_at_contact = support_z + ctx.memory.grasp_offset_z_m
    yaw = ctx.current_yaw()
    # the object's centre, not the hand, over the target (they differ for a rim grasp)
    held_offset = _rot2(_hand_yaw(ctx.top_down(ctx.tcp.position_m, yaw).rotation)) @ ctx.memory.grasp_offset_xy_hand_m
    xy = target.position_m[:2] + np.asarray(offset_xy, float) - held_offset
    above = ctx.top_down(
        [xy[0], xy[1], max(tcp_at_contact, target.top_z_m + ctx.memory.grasp_offset_z_m) + 0.06 + 0.02], yaw
    )
    if ctx.tcp.position_m[2] < above.position_m[2] - 0.01:  # rise first: never drag the load low across the scene
        ctx.motion.move_line(
            ctx.tcp.translated([0, 0, above.position_m[2] - ctx.tcp.position_m[2]]), what="carry height", check=False
        )
    out = ctx.motion.move_to(above, what=f"point above the {what} {target.label!r}")
    if not out.ok:
        return out
    rotation = _tilted(ctx, tilt_rad, above.rotation)
    lowest = Pose(np.array([xy[0], xy[1], tcp_at_contact - 0.03]), rotation)
    out = ctx.motion.move_line(lowest, speed_m_s=0.06, stop=ctx.contact(CONTACT_FORCE_N), what="support", check=False)
    if not out.detail.get("stopped_early"):
        open_gripper(ctx)
        ctx.memory.held_label = None
        ctx.motion.move_line(ctx.tcp.translated([0, 0, 0.08]), check=False)
        return ctx.fail(
            f"no support felt at the {what} {target.label!r} (expected near z={support_z:.3f} m): "
            "it moved or is not there",
            FailureKind.PERCEPTION,
        )
    felt_z = float(ctx.tcp.position_m[2])
    if felt_z < tcp_at_contact - SUPPORT_TOL_M:  # support much lower than the target's top: the target is gone
        ctx.motion.move_line(ctx.tcp.translated([0, 0, 0.08]), check=False)  # keep holding: a retry re-detects
        return ctx.fail(
            f"support felt {100 * (tcp_at_contact - felt_z):.1f} cm below the top of the {what} "
            f"{target.label!r}: it moved or is not there",
            FailureKind.PERCEPTION,
        )
    return _let_go(ctx, felt_z)


def _tilted(ctx: Ctx, tilt_rad: float, rotation: np.ndarray) -> np.ndarray:
    """`rotation` (the hand's), tilted by `tilt_rad` about the fingers' closing axis; the hand turns to it in place.
    Unchanged (and no motion) when the tilt is 0."""
    if tilt_rad:
        rotation = rotation @ rot_y(tilt_rad)
        ctx.motion.move_line(Pose(ctx.tcp.position_m, rotation), speed_m_s=0.1, what="release tilt", check=False)
    return rotation


def _let_go(ctx: Ctx, felt_z: float) -> ActionOutcome:
    """Open on the felt support, forget the load, back straight up; fail when it stays between the fingers."""
    open_gripper(ctx)
    ctx.memory.held_label = None
    ctx.motion.move_line(ctx.tcp.translated([0, 0, 0.08]), what="retreat", check=False)
    if ctx.world.pinched_bodies(ctx.arm):
        return ctx.fail("object stuck to the gripper after release")
    return ActionOutcome.success(0.0, contact_tcp_z_m=round(felt_z, 4))


def set_down_here(ctx: Ctx, tilt_rad: float = 0.0) -> ActionOutcome:
    """Put the held object down right where the hand is: lower straight down until the wrist feels support (the
    table, or whatever is below), release, retract. Nothing felt down to the table means nothing is carried."""
    if not ctx.holding():
        return ctx.fail("nothing in the gripper to set down")
    rotation = _tilted(ctx, tilt_rad, ctx.tcp.rotation)
    start = ctx.tcp.position_m
    lowest = Pose(np.array([start[0], start[1], ctx.memory.grasp_offset_z_m - 0.03]), rotation)
    out = ctx.motion.move_line(lowest, speed_m_s=0.06, stop=ctx.contact(CONTACT_FORCE_N), what="support", check=False)
    if not out.detail.get("stopped_early"):
        open_gripper(ctx)
        ctx.memory.held_label = None
        ctx.motion.move_line(ctx.tcp.translated([0, 0, 0.08]), check=False)
        return ctx.fail("no support felt below the hand down to the table")
    return _let_go(ctx, float(ctx.tcp.position_m[2]))


@primitive("place")
def place(ctx: Ctx) -> ActionOutcome:
    a = ctx.args
    return put_down(ctx, ctx.kp("target_label"), (a.get("offset_x", 0.0), a.get("offset_y", 0.0)))


@primitive("place_in")
def place_in(ctx: Ctx) -> ActionOutcome:
    c = ctx.kp("container_label")
    floor = c.position_m[2] - c.extent_m[2] / 2 + 0.01
    return put_down(ctx, c, floor_z=floor, what="container")


@primitive("stack")
def stack(ctx: Ctx) -> ActionOutcome:
    out = pick_and_lift(ctx, ctx.kp("keypoint_label"), 0.10)
    return put_down(ctx, ctx.kp("target_label")) if out.ok else out


@primitive("hang")
def hang(ctx: Ctx) -> ActionOutcome:
    if not ctx.holding():
        out = grasp_object(ctx, ctx.kp("keypoint_label"))
        if not out.ok:
            return out
        lift_held(ctx, 0.1)
    return put_down(ctx, ctx.kp("target_label"), what="hook")


@primitive("insert")
def insert(ctx: Ctx) -> ActionOutcome:
    """Lower the held object into the opening at the keypoint, compliant (stop on contact), then release."""
    if not ctx.holding():
        return ctx.fail("insert with nothing in the gripper")
    hole = ctx.kp("keypoint_label")
    off = ctx.memory.grasp_offset_z_m
    yaw = ctx.current_yaw()
    above = ctx.top_down([hole.position_m[0], hole.position_m[1], hole.top_z_m + off + 0.04], yaw)
    out = ctx.motion.move_to(above, what=f"point above {hole.label!r}")
    if not out.ok:
        return out
    goal_z = hole.top_z_m - ctx.args["depth"] + off
    out = ctx.motion.move_line(
        ctx.top_down([hole.position_m[0], hole.position_m[1], goal_z], yaw),
        speed_m_s=0.04,
        stop=ctx.contact(8.0),
        what="insertion depth",
        check=False,
    )
    reached = ctx.tcp.position_m[2] <= goal_z + 0.01
    open_gripper(ctx)
    ctx.memory.held_label = None
    ctx.motion.move_line(ctx.tcp.translated([0, 0, 0.08]), check=False)
    if not reached:
        return ctx.fail(f"jammed {100 * (ctx.tcp.position_m[2] - goal_z):.1f} cm above the insertion depth")
    return ActionOutcome.success(0.0)


def _wrap(angle: float, period: float = 2 * np.pi) -> float:
    return float((angle + period / 2) % period - period / 2)


@primitive("place_over")
def place_over(ctx: Ctx) -> ActionOutcome:
    """The held object's centre (seen now, in the hand) goes over the peg: the TCP target is the peg minus the
    object's offset from the TCP, turned by the wrist rotation that lines the object's sides up with the peg's
    (square openings: modulo 90 degrees). Compliant descent to the peg's base; stopping high means it jammed."""
    if not ctx.holding():
        return ctx.fail("place_over with nothing in the gripper")
    obj, peg = ctx.kp("keypoint_label"), ctx.kp("target_label")
    tcp = ctx.tcp
    turn = 0.0
    if obj.yaw_rad is not None and peg.yaw_rad is not None:
        turn = _wrap(peg.yaw_rad - obj.yaw_rad, np.pi / 2)
    actual_yaw = float(np.arctan2(tcp.rotation[1, 0], tcp.rotation[0, 0]))
    base_xy = ctx.world.kinematics[ctx.arm].T_world_base[:2, 3]
    options = []  # a square opening fits every quarter turn: take the one that keeps the hand nearest the base
    for k in range(4):
        yaw = ctx.current_yaw() + turn + k * np.pi / 2
        R = ctx.top_down(tcp.position_m, yaw).rotation
        applied = _wrap(float(np.arctan2(R[1, 0], R[0, 0])) - actual_yaw)  # the wrist's real turn, incl. any flip
        c, s = np.cos(applied), np.sin(applied)
        xy = peg.position_m[:2] - np.array([[c, -s], [s, c]]) @ (obj.position_m[:2] - tcp.position_m[:2])
        options.append((float(np.linalg.norm(xy - base_xy)), yaw, applied, xy))
    _, yaw, applied, xy = min(options, key=lambda o: o[0])
    tcp_above_bottom = float(tcp.position_m[2] - (obj.position_m[2] - obj.extent_m[2] / 2))
    above = ctx.top_down([xy[0], xy[1], peg.top_z_m + tcp_above_bottom + 0.03], yaw)
    out = ctx.motion.move_to(above, what=f"point above {peg.label!r}")
    if not out.ok:
        return out
    for _ in range(3):  # look again and close the remaining gap: openings leave millimetres of clearance
        now = ctx.observe(obj.label)
        if now is None:
            break
        gap = peg.position_m[:2] - now.position_m[:2]
        if np.linalg.norm(gap) < 0.002:
            break
        xy = xy + gap
        ctx.motion.move_line(
            ctx.top_down([xy[0], xy[1], above.position_m[2]], yaw),
            speed_m_s=0.05,
            what="centre over the peg",
            check=False,
        )
    base_z = max(peg.position_m[2] - peg.extent_m[2] / 2, 0.0)  # a peg may be sunk into the table (z = 0)
    goal_z = base_z + tcp_above_bottom + 0.004
    ctx.motion.move_line(
        ctx.top_down([xy[0], xy[1], goal_z], yaw),
        speed_m_s=0.05,
        stop=ctx.contact(10.0),
        what=f"base of {peg.label!r}",
        check=False,
    )
    bottom_z = float(ctx.tcp.position_m[2] - tcp_above_bottom)  # where the object's underside got to
    open_gripper(ctx)
    ctx.memory.held_label = None
    ctx.motion.move_line(ctx.tcp.translated([0, 0, 0.10]), what="retreat", check=False)
    through_m = peg.top_z_m - bottom_z
    if through_m < min(0.03, 0.5 * (peg.top_z_m - base_z)):
        return ctx.fail(
            f"{obj.label!r} jammed: its underside stopped {100 * (bottom_z - base_z):.1f} cm above the "
            f"base of {peg.label!r}, {100 * max(through_m, 0.0):.1f} cm down the peg"
        )
    if ctx.world.pinched_bodies(ctx.arm):
        return ctx.fail("object stuck to the gripper after release")
    return ActionOutcome.success(0.0, turned_rad=round(applied, 4))


@primitive("drag")
def drag(ctx: Ctx) -> ActionOutcome:
    kp, target = ctx.kp("keypoint_label"), ctx.kp("target_label")
    out = grasp_object(ctx, kp)
    if not out.ok:
        return out
    lift_held(ctx, 0.005)
    goal = ctx.tcp.position_m.copy()
    goal[:2] = target.position_m[:2]
    out = ctx.motion.move_line(ctx.top_down(goal), speed_m_s=0.08, what=f"{target.label!r}")
    open_gripper(ctx)
    ctx.memory.held_label = None
    ctx.motion.move_line(ctx.tcp.translated([0, 0, 0.08]), check=False)
    return out
