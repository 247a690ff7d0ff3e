"""Contact-rich motions along the table: push, sweep, wipe, wipe an area clean, constrained scrub."""

from __future__ import annotations

import numpy as np

from ...control.ik import Unreachable
from ...control.pose import wrap_grasp_yaw
from ..protocols import ActionOutcome, FailureKind
from .base import Ctx, primitive
from .coverage import coverage_strokes

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
    out = ctx.motion.move_to(
        [ctx.top_down(start + [0, 0, 0.1], yaw), ctx.top_down(start, yaw)], what=f"point behind {kp.label!r}"
    )
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
            return ctx.fail(
                f"{kp.label!r} was lifted or tipped ({100 * (after.position_m[2] - before[2]):.1f} cm up) "
                "instead of sliding"
            )
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


WIPE_PRESS_M = 0.008  # below first touch: a soft pad's face gives, so it stays pressed flat on the surface
WIPE_SPEED_M_S = 0.1
WIPE_REACH_BELOW_M = 0.015  # how far below the seen surface the pressed path must be reachable


def _footprint(kp) -> np.ndarray:
    """Where the region is (xy, m): perception's 1 cm cover of its top face, else its box."""
    pts = kp.detail.get("footprint_xy_m")
    if pts:
        return np.asarray(pts, float)
    half = kp.extent_m[:2] / 2
    gx, gy = (np.arange(-h, h + 1e-9, 0.01) if h > 0.005 else np.zeros(1) for h in half)
    return np.array([[kp.position_m[0] + x, kp.position_m[1] + y] for x in gx for y in gy])


def _stroke_yaw(ctx: Ctx, waypoints: list[np.ndarray], heading: float, surface_z_m: float) -> float | None:
    """Of the two hand yaws that hold the tool across the strokes (it is symmetric under a half turn), one whose
    whole pressed path the arm can follow in straight lines without reaching a joint limit; None if neither."""
    for yaw in (wrap_grasp_yaw(heading), wrap_grasp_yaw(heading) + np.pi):
        try:
            above = ctx.top_down([*waypoints[0], surface_z_m + 0.05], yaw)
            q = ctx.motion.ik(above, what="point above the region")
            start = above
            for p in [waypoints[0], *waypoints]:
                pose = ctx.top_down([*p, surface_z_m - WIPE_REACH_BELOW_M], yaw)
                q = ctx.motion.plan_line(pose, q_start=q, start=start)[-1]
                start = pose
            return yaw
        except Unreachable:
            continue
    return None


def _pressed_path(ctx: Ctx, waypoints: list[np.ndarray], yaw: float, surface_z_m: float, label: str) -> ActionOutcome:
    """Touch down at the first waypoint, slide pressed through the rest, lift off."""
    above = ctx.top_down([*waypoints[0], surface_z_m + 0.05], yaw)
    out = ctx.motion.move_to(above, what=f"point above {label!r}")
    if not out.ok:
        return out
    down = ctx.top_down([*waypoints[0], surface_z_m - WIPE_REACH_BELOW_M], yaw)
    out = ctx.motion.move_line(down, speed_m_s=0.04, stop=ctx.contact(), check=False)
    if not out.ok:
        return out
    if not out.detail.get("stopped_early"):
        return ctx.fail(
            f"the tool never touched the surface under {label!r} (TCP at z={ctx.tcp.position_m[2]:.3f} m)",
            FailureKind.PERCEPTION,
        )
    z = ctx.tcp.position_m[2] - WIPE_PRESS_M
    touching, length = 0, 0.0
    for p in waypoints:
        length += float(np.linalg.norm(p - ctx.tcp.position_m[:2]))
        ctx.motion.move_line(ctx.top_down([*p, z], yaw), speed_m_s=WIPE_SPEED_M_S, check=False)
        touching += ctx.world.wrist_force_n(ctx.arm) > 0.5
    ctx.motion.move_line(ctx.tcp.translated([0, 0, 0.1]), check=False)
    if touching < 0.7 * len(waypoints):
        return ctx.fail(
            f"the tool lost contact with the surface on {len(waypoints) - touching} of {len(waypoints)} strokes"
        )
    return ActionOutcome.success(0.0, path_m=round(length, 3))


@primitive("wipe_area")
def wipe_area(ctx: Ctx) -> ActionOutcome:
    """Cover what is seen of the region in serpentine strokes as wide as the tool, look again from the rest
    pose (the arm out of the cameras' way), and cover what is left."""
    if not ctx.holding():
        return ctx.fail("nothing held to wipe with")
    if ctx.resolver is None:
        return ctx.fail("no perception to tell whether the region is clean", FailureKind.PERCEPTION)
    robot = ctx.world.kinematics[ctx.arm].robot
    if robot.gripper.mounted_tool:
        width = robot.gripper.tool_size_m[1]  # the pad's long side, held across the stroke
    else:
        held = ctx.memory.held_extent_m
        width = float(np.max(held[:2])) if held is not None else 0.04
    kp, label, path = ctx.kp("keypoint_label"), ctx.args["keypoint_label"], 0.0
    for n in range(1, ctx.args["max_passes"] + 1):
        # strokes end 1 cm past the last point: the tool's own length covers the rest
        strokes, heading = coverage_strokes(_footprint(kp), stripe_m=0.75 * width, margin_m=0.01)
        yaw = _stroke_yaw(ctx, strokes, heading, kp.top_z_m)
        if yaw is None:
            return ctx.fail(f"the strokes over {label!r} are out of the arm's reach", FailureKind.KINEMATIC_LIMIT)
        out = _pressed_path(ctx, strokes, yaw, kp.top_z_m, label)
        if not out.ok:
            return out
        path += out.detail["path_m"]
        ctx.motion.move_joints(robot.home_q_rad, what="rest pose")
        seen = ctx.observe(label)
        if seen is None:
            return ActionOutcome.success(0.0, passes=n, wiped_path_m=round(path, 3))
        kp = seen
    return ctx.fail(f"{label!r} still seen after {n} passes: {len(_footprint(kp))} cm2 of it left")
