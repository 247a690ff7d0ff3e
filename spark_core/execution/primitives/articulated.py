"""Articulated objects and in-hand rotations: drawers, knobs, pulling, pressing, screwing."""

from __future__ import annotations

import numpy as np

from ...control.pose import Pose, rot_z
from ...perception import Keypoint
from ..protocols import ActionOutcome, FailureKind
from .base import Ctx, primitive
from .gripper import grasp, open_gripper
from .pick_place import grasp_object

PULL_SPEED_M_S = 0.2


def handle_facing(ctx: Ctx, kp: Keypoint) -> np.ndarray:
    """The way a handle faces (unit, horizontal, world): away from the object it belongs to (a drawer handle from
    its drawer or cabinet), along one of that object's sides; toward the robot (-x) when perception knows no such
    object. A drawer opens along it."""
    return facing_from_wholes(kp, list(ctx.wholes_of(kp.label)))


FACE_FLOOR_M = 0.005  # a side's half depth is at least this: a drawer front seen face-on is a few mm deep


def facing_from_wholes(part: Keypoint, wholes: list[Keypoint]) -> np.ndarray:
    """Which face of its wholes a part sits on: over every whole and each of its four sides, the part's offset
    from the whole's centre along the side, as a fraction of the whole's half depth that way; the largest wins.
    A point on a face is about one half depth out along it and less than that across, whatever its place on the
    face: unlike the bare offset, this tells a handle near a drawer front's end (2 cm along the front, 1 cm out)
    and a part seen only in part from the side it is on. -x when there is no whole, or the part is at a centre."""
    best, best_ratio = np.array([-1.0, 0.0, 0.0]), 0.0
    for whole in wholes:
        d = part.position_m[:2] - whole.position_m[:2]
        base = whole.yaw_rad or 0.0
        for k in range(4):
            a = base + k * np.pi / 2
            v = np.array([np.cos(a), np.sin(a)])
            half = max(0.5 * float(np.dot(np.abs(v), whole.extent_m[:2])), FACE_FLOOR_M)
            out_m = float(np.dot(d, v))
            if out_m / half > best_ratio and out_m > 0.005:
                best, best_ratio = np.array([v[0], v[1], 0.0]), out_m / half
    return best


def _handle_rotations(kp: Keypoint, facing: np.ndarray) -> list[np.ndarray]:
    """Hand rotations that approach against `facing` with the fingers closing across the bar: vertically round a
    bar lying along the front, horizontally round an upright one (our cabinet's). Two, a half turn apart about
    the approach axis (the fingers are symmetric): the first is SIDE_ROTATION for a handle facing -x."""
    along_front = np.cross([0.0, 0.0, 1.0], facing)
    lying = abs(float(np.dot(np.abs(along_front), kp.extent_m))) > kp.extent_m[2]
    z = -facing
    y = np.array([0.0, 0.0, 1.0]) if lying else -along_front
    R = np.column_stack([np.cross(y, z), y, z])
    return [R, R @ np.diag([-1.0, -1.0, 1.0])]


def _grasp_handle(ctx: Ctx, label_slot: str = "keypoint_label") -> tuple[ActionOutcome, np.ndarray, np.ndarray]:
    """Approach the handle against the way it faces, fingers closing across the bar. Returns the outcome, the
    facing (the pull direction) and the hand rotation used."""
    kp = ctx.kp(label_slot)
    n = handle_facing(ctx, kp)
    depth = float(np.dot(np.abs(n), kp.extent_m))
    at = kp.position_m + n * (depth / 2 - 0.01)  # finger pads 1 cm behind the handle's front face, around the grip
    open_gripper(ctx)
    # A big wrist reorientation (e.g. the UR10 turning from top-down to sideways) happens above and in front of
    # the handle, in free space, then the hand descends to the approach point.
    out = ActionOutcome.fail(f"no hand orientation reaches {kp.label!r}", FailureKind.KINEMATIC_LIMIT)
    for R in _handle_rotations(kp, n):
        out = ctx.motion.move_to(
            Pose(at + 0.06 * n, R), what=f"approach to {kp.label!r}", reconfigure_via=0.08 * n + [0.0, 0.0, 0.15]
        )
        if out.ok or out.failure is not FailureKind.KINEMATIC_LIMIT:
            break
    if not out.ok:
        return out, n, R
    out = ctx.motion.move_line(Pose(at, R), speed_m_s=0.15, what=f"{kp.label!r}", stop=ctx.contact(15.0), check=False)
    ctx.args = {**ctx.args, "force": 60.0, "target_width": None}
    return grasp(ctx), n, R


class _PullWatch:
    """Watches a pull every control period: a stop condition once the hand has come `after_m` along `facing` and
    then gained under `eps_m` in the last `window` periods (a drawer on its end stop), and how far the hand had
    come when the handle was last pinched."""

    def __init__(
        self,
        ctx: Ctx,
        start: np.ndarray,
        facing: np.ndarray,
        after_m: float = 0.05,
        window: int = 20,
        eps_m: float = 0.002,
    ):
        self.ctx, self.start, self.facing = ctx, start, facing
        self.after_m, self.window, self.eps_m = after_m, window, eps_m
        self.progress: list[float] = []
        self.pinched_until_m = 0.0

    def __call__(self) -> bool:
        p = float(np.dot(self.ctx.tcp.position_m - self.start, self.facing))
        self.progress.append(p)
        if self.ctx.holding():
            self.pinched_until_m = p
        w = self.window
        return p > self.after_m and len(self.progress) > w and p - self.progress[-1 - w] < self.eps_m


def _pull_held(
    ctx: Ctx, distance: float, what: str, facing: np.ndarray, R: np.ndarray, handle: Keypoint | None = None
) -> ActionOutcome:
    """Pull along the handle's facing while holding, up to `distance` or the end stop. Success: the hand
    travelled at least 80 % of the distance and the handle came with it: seen again where the hand took it
    (when perception finds it there), else still pinched when the pull ended."""
    start = ctx.tcp.position_m.copy()
    # not fast: a drawer's damping (LIBERO's: 50 N s/m) resists in proportion to speed, and the grip is friction
    watch = _PullWatch(ctx, start, facing)  # stops at the drawer's end stop: pulling on only slips
    ctx.motion.move_line(Pose(start + distance * facing, R), speed_m_s=PULL_SPEED_M_S, check=False, stop=watch)
    travelled = float(np.dot(ctx.tcp.position_m - start, facing))
    held = watch.pinched_until_m >= 0.9 * travelled  # pinched to (nearly) the end of the pull
    open_gripper(ctx)
    # back and up, clear of the drawer: the next (often joint-space) move must not sweep the hand through it
    ctx.motion.move_line(Pose(ctx.tcp.position_m + 0.10 * facing + [0, 0, 0.12], R), speed_m_s=0.4, check=False)
    if travelled < 0.8 * distance:
        return ctx.fail(f"the {what} moved only {travelled * 100:.1f} of {distance * 100:.0f} cm: blocked")
    moved = _handle_moved(ctx, handle, facing, travelled) if handle is not None else None
    if moved is None and not held:
        return ctx.fail(f"the {what} slipped out of the gripper while pulling")
    if moved is not None and moved < 0.8 * travelled:
        return ctx.fail(
            f"the {what} came {moved * 100:.1f} cm of the hand's {travelled * 100:.1f} cm: it slipped in the fingers"
        )
    return ActionOutcome.success(
        0.0, travelled_m=round(travelled, 4), **({} if moved is None else {"moved_m": round(moved, 4)})
    )


def _handle_moved(ctx: Ctx, handle: Keypoint, facing: np.ndarray, travelled: float) -> float | None:
    """How far (m, along `facing`) perception now sees the handle from where it was; None when it is not seen
    where it was or where the hand took it (then it is another drawer's handle, or hidden)."""
    seen = ctx.observe(handle.label)
    if (
        seen is None
        or min(
            np.linalg.norm(seen.position_m - handle.position_m),
            np.linalg.norm(seen.position_m - handle.position_m - travelled * facing),
        )
        > 0.03
    ):
        return None
    return float(np.dot(seen.position_m - handle.position_m, facing))


@primitive("open_drawer")
@primitive("pull")
def pull(ctx: Ctx) -> ActionOutcome:
    """Grasp the handle at the keypoint and pull it toward the robot (a drawer is opened the same way)."""
    out, facing, R = _grasp_handle(ctx)
    if not out.ok:
        return out
    return _pull_held(
        ctx,
        ctx.args["distance"],
        "drawer" if "drawer" in ctx.args["keypoint_label"] else "handle",
        facing,
        R,
        ctx.kp("keypoint_label"),
    )


@primitive("close_drawer")
def close_drawer(ctx: Ctx) -> ActionOutcome:
    """Push the drawer front with open fingers (the handle passes between them, so nothing hooks it on the way
    back) until the drawer sits on its end stop (sustained force)."""
    kp = ctx.kp("keypoint_label")
    open_gripper(ctx)
    at = kp.position_m.copy()
    n = handle_facing(ctx, kp)
    out = ActionOutcome.fail(f"no hand orientation reaches {kp.label!r}", FailureKind.KINEMATIC_LIMIT)
    for R in _handle_rotations(kp, n):
        out = ctx.motion.move_to(Pose(at + 0.08 * n, R), what=f"approach to {kp.label!r}")
        if out.ok or out.failure is not FailureKind.KINEMATIC_LIMIT:
            break
    if not out.ok:
        return out
    out = ctx.motion.move_line(
        Pose(at - 0.30 * n, R), speed_m_s=0.15, stop=ctx.sustained_contact(25.0, ticks=5), check=False
    )
    ctx.motion.move_line(Pose(ctx.tcp.position_m + 0.08 * n, R), check=False)
    if not out.detail.get("stopped_early"):
        return ctx.fail(
            "pushed 30 cm without reaching the drawer's end stop: the drawer is not where expected",
            FailureKind.PERCEPTION,
        )
    return ActionOutcome.success(0.0)


def _rotate_held(ctx: Ctx, angle_rad: float) -> ActionOutcome:
    tcp = ctx.tcp
    out = ctx.motion.move_line(
        Pose(tcp.position_m, rot_z(angle_rad) @ tcp.rotation), speed_m_s=0.05, what="rotated grip", check=False
    )
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
    out = ctx.motion.move_line(
        above.translated([0, 0, -0.12]), speed_m_s=0.04, stop=ctx.contact(ctx.args["force_n"]), check=False
    )
    ctx.motion.move_line(ctx.tcp.translated([0, 0, 0.06]), check=False)
    if not out.detail.get("stopped_early"):
        return ctx.fail(f"no contact reached at {kp.label!r}", FailureKind.PERCEPTION)
    return ActionOutcome.success(0.0)
