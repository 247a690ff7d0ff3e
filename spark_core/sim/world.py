"""MuJoCo implementation of the World protocol: joint trajectories tracked by position actuators, a
force-limited gripper, touch sensing, on-demand cameras, and (privileged) ground-truth state for oracles."""

from __future__ import annotations

import threading
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import mujoco
import numpy as np

from ..control.kinematics import ArmKinematics
from ..control.pose import Pose
from ..control.trajectory import JointTrajectory
from .scene import Scene

if TYPE_CHECKING:
    from concurrent.futures import ThreadPoolExecutor

CONTROL_DT_S = 0.01  # control period; physics runs at the scene's timestep underneath


@dataclass
class TrajectoryRecorder:
    """Joint states at the control rate (t_s, arm, q_rad, gripper_width_m), and the whole scene state
    (t_s, qpos) every `state_period_s` of simulated time, enough to replay the trial in a viewer."""

    rows: list[tuple[float, str, list[float], float]] = field(default_factory=list)
    states: list[tuple[float, list[float]]] = field(default_factory=list)
    state_period_s: float = 0.04


@dataclass(frozen=True)
class ExecResult:
    completed: bool  # False when `stop` ended the motion early
    sim_time_s: float
    tracking_error_rad: float  # max |q - q_cmd| at the end


class MujocoWorld:
    """One simulated tabletop. Thread-safe: arms may be commanded from different threads; physics steps
    are serialised under a lock (two arms interleave at control-period granularity)."""

    def __init__(self, scene: Scene, data: mujoco.MjData | None = None, origin_m=None):
        self.scene = scene
        self.model = scene.model
        self.data = mujoco.MjData(self.model) if data is None else data
        # Where this world's frame origin sits in MuJoCo coordinates. Our scenes put it at the robot base on the
        # table top (zero); adapters of other simulators (robosuite) shift it there so primitives see one frame.
        self.origin_m = np.zeros(3) if origin_m is None else np.asarray(origin_m, float)
        self.arms: tuple[str, ...] = tuple(scene.robots)
        self.kinematics = {a: ArmKinematics(scene.robot_descriptions[a], scene.T_world_base[a]) for a in self.arms}
        m = self.model
        self._qadr = {a: np.array([m.joint(j).qposadr[0] for j in n.arm_joints]) for a, n in scene.robots.items()}
        self._dadr = {a: np.array([m.joint(j).dofadr[0] for j in n.arm_joints]) for a, n in scene.robots.items()}
        self._act = {a: np.array([m.actuator(x).id for x in n.arm_actuators]) for a, n in scene.robots.items()}
        self._grip = {a: m.actuator(n.gripper_actuator).id for a, n in scene.robots.items() if n.gripper_actuator}
        self._fingers = {a: [m.joint(f).qposadr[0] for f in n.finger_joints] for a, n in scene.robots.items()}
        # finger -> the bodies that touch with it (a finger and, where the model has them, its pad bodies)
        self._finger_bodies = {
            a: {m.body(b).id: _subtree(m, m.body(b).id) for b in n.finger_bodies} for a, n in scene.robots.items()
        }
        self._robot_bodies = {m.body(b).id for n in scene.robots.values() for b in n.bodies}
        self._tcp = {a: m.site(n.tcp_site).id for a, n in scene.robots.items()}
        hands = {a: m.site(n.tcp_site).bodyid for a, n in scene.robots.items()}  # the TCP body
        self._hand_bodies = {
            a: {b for b in range(m.nbody) if b == m.body_parentid[h] or _is_descendant(m, b, m.body_parentid[h])}
            for a, h in hands.items()
        }
        self._lock = threading.RLock()
        self.recorder: TrajectoryRecorder | None = None
        self.target_tcp: dict[str, Pose] = {}  # the TCP pose the current joint trajectory ends at, per arm
        self.claims_lock = threading.Lock()  # arms check each other's targets and claim their own under it
        self.monitors: list[Callable[[MujocoWorld], None]] = []  # called every control period (task metrics)
        self.renderer = None
        self._render_pool: ThreadPoolExecutor | None = None  # created on first use: see on_render_thread
        self.wall_s = {"simulation": 0.0, "rendering": 0.0}  # wall seconds spent stepping physics / drawing cameras
        self.reset()

    # -- state -------------------------------------------------------------------------------------------------
    def reset(self) -> None:
        with self._lock:
            mujoco.mj_resetData(self.model, self.data)
            for a in self.arms:
                q = self.scene.robot_descriptions[a].home_q_rad
                self.data.qpos[self._qadr[a]] = q
                self.data.ctrl[self._act[a]] = q
                if a not in self._grip:
                    continue
                self.data.ctrl[self._grip[a]] = self.scene.robot_descriptions[a].gripper.max_width_m / 2
                self.data.qpos[self._fingers[a]] = self.scene.robot_descriptions[a].gripper.max_width_m / 2
            mujoco.mj_forward(self.model, self.data)

    @property
    def sim_time_s(self) -> float:
        return float(self.data.time)

    def q(self, arm: str) -> np.ndarray:
        return self.data.qpos[self._qadr[arm]].copy()

    def qd(self, arm: str) -> np.ndarray:
        """Joint velocities (rad/s)."""
        return self.data.qvel[self._dadr[arm]].copy()

    def joint_command(self, arm: str) -> np.ndarray:
        """The joint position targets the arm's actuators are tracking (rad): the commanded action."""
        return self.data.ctrl[self._act[arm]].copy()

    def _command_joints(self, arm: str, q_rad: np.ndarray, qd_rad_s: np.ndarray | None = None) -> None:
        """Set the joint targets the arm tracks from now on (position actuators track them in physics)."""
        self.data.ctrl[self._act[arm]] = q_rad

    def gripper_command_m(self, arm: str) -> float:
        """The commanded finger gap (m); the sensed gap is `gripper_width_m`."""
        return float(2 * self.data.ctrl[self._grip[arm]]) if arm in self._grip else 0.0

    def _command_gripper(self, arm: str, width_m: float) -> None:
        self.data.ctrl[self._grip[arm]] = width_m / 2

    def _limit_gripper_force(self, arm: str, force_n: float) -> None:
        self.model.actuator_forcerange[self._grip[arm]] = [-force_n, force_n]

    def tcp_pose(self, arm: str) -> Pose:
        sid = self._tcp[arm]
        return Pose(self.data.site_xpos[sid] - self.origin_m, self.data.site_xmat[sid].reshape(3, 3).copy())

    def gripper_width_m(self, arm: str) -> float:
        """Finger gap in metres (the width sensor); 0 for a mounted tool."""
        return float(np.abs(self.data.qpos[self._fingers[arm]]).sum())

    def finger_contacts(self, arm: str) -> dict[int, set[int]]:
        """Touch sensing: for each finger body id, the non-robot body ids it touches."""
        fingers = self._finger_bodies[arm]
        out: dict[int, set[int]] = {f: set() for f in fingers}
        owner = {b: f for f, bodies in fingers.items() for b in bodies}
        m, d = self.model, self.data
        with self._lock:  # another arm's thread may be stepping: read one consistent contact list
            contacts = [(d.contact[i].geom1, d.contact[i].geom2) for i in range(d.ncon)]
        for g1, g2 in contacts:
            b1, b2 = m.geom_bodyid[g1], m.geom_bodyid[g2]
            for f, o in ((b1, b2), (b2, b1)):
                if f in owner and o not in self._robot_bodies:
                    out[owner[f]].add(int(o))
        return out

    def pinched_bodies(self, arm: str) -> set[int]:
        """Bodies touched by both fingers at once (what the gripper is holding)."""
        sets = list(self.finger_contacts(arm).values())
        return set.intersection(*sets) if sets else set()

    def wrist_force_n(self, arm: str) -> float:
        """Simulated wrist force sensor (N): normal contact force on the hand and whatever it holds, from
        anything that is neither the robot nor the held object itself."""
        m, d = self.model, self.data
        held = self.pinched_bodies(arm)
        inside = self._hand_bodies[arm] | held
        total = 0.0
        f6 = np.zeros(6)
        with self._lock:  # a consistent contact list while another arm's thread steps
            for i in range(d.ncon):
                c = d.contact[i]
                b1, b2 = m.geom_bodyid[c.geom1], m.geom_bodyid[c.geom2]
                for a, b in ((b1, b2), (b2, b1)):
                    if a in inside and b not in inside and b not in self._robot_bodies:
                        mujoco.mj_contactForce(m, d, i, f6)
                        total += abs(f6[0])
                        break
        return total

    # -- actuation ---------------------------------------------------------------------------------------------
    def _tick(self, steps: int) -> None:
        t0 = time.perf_counter()
        mujoco.mj_step(self.model, self.data, nstep=steps)
        self.wall_s["simulation"] += time.perf_counter() - t0
        for monitor in self.monitors:
            monitor(self)

    def _record(self, arm: str) -> None:
        rec = self.recorder
        if rec is not None:
            t = self.sim_time_s
            rec.rows.append((t, arm, self.q(arm).round(5).tolist(), round(self.gripper_width_m(arm), 5)))
            if not rec.states or t - rec.states[-1][0] >= rec.state_period_s - 1e-9:
                rec.states.append((t, self.data.qpos.round(5).tolist()))

    def execute(
        self, arm: str, traj: JointTrajectory, stop: Callable[[], bool] | None = None, settle_s: float = 0.05
    ) -> ExecResult:
        """Track a joint trajectory at the control rate; `stop()` is checked every control period."""
        n_sub = max(int(round(CONTROL_DT_S / self.model.opt.timestep)), 1)
        t0 = self.sim_time_s
        completed = True
        if len(traj.q_rad):  # where this motion is taking the TCP (shown live in the 3D view)
            self.target_tcp[arm] = self.kinematics[arm].fk(np.asarray(traj.q_rad[-1]))
        for q_cmd, qd_cmd in zip(traj.q_rad, traj.qd_rad_s):
            with self._lock:
                self._command_joints(arm, q_cmd, qd_cmd)
                self._tick(n_sub)
                self._record(arm)
                if stop is not None and stop():
                    self._command_joints(arm, self.q(arm))  # hold where contact stopped us
                    completed = False
                    break
        if completed:
            with self._lock:
                self._command_joints(arm, self.joint_command(arm))  # the end point, at rest
            if settle_s > 0:
                self.settle(settle_s)
        err = float(np.max(np.abs(self.q(arm) - self.joint_command(arm))))
        return ExecResult(completed, self.sim_time_s - t0, err)

    def set_gripper(self, arm: str, width_m: float, force_n: float, duration_s: float = 0.6) -> float:
        """Drive the fingers toward `width_m` with at most `force_n` (N); returns the simulated seconds spent.
        An arm with a mounted tool has no fingers: nothing moves and no time passes."""
        g = self.scene.robot_descriptions[arm].gripper
        if arm not in self._grip:
            return 0.0
        width_m = float(np.clip(width_m, 0.0, g.max_width_m))
        force_n = float(np.clip(force_n, 1.0, g.max_force_n))
        n_sub = max(int(round(CONTROL_DT_S / self.model.opt.timestep)), 1)
        t0 = self.sim_time_s
        with self._lock:
            self._limit_gripper_force(arm, force_n)
        if abs(self.gripper_command_m(arm) - width_m) < 1e-9 and abs(self.gripper_width_m(arm) - width_m) < 0.002:
            return 0.0  # already there (opening an open hand): nothing to wait for
        # The finger set-point moves at the finger speed (a stiff servo tracking a ramp): fingers never slam
        # through thin parts, and on contact the servo error grows until the force limit caps the squeeze.
        step = 2 * g.finger_speed_m_s * CONTROL_DT_S
        while abs(self.gripper_command_m(arm) - width_m) > 1e-9:
            with self._lock:
                c = self.gripper_command_m(arm)
                self._command_gripper(
                    arm, width_m if abs(width_m - c) <= step else c + float(np.sign(width_m - c)) * step
                )
                self._tick(n_sub)
                self._record(arm)
        remaining = duration_s - (self.sim_time_s - t0)
        if remaining > 0:
            self.settle(remaining, arm)
        # Like a gripper driver's "motion complete": wait (at most 1 s more) while the fingers are still moving,
        # e.g. heavily damped fingers (robosuite's) lagging the set-point.
        for _ in range(100):
            before = self.gripper_width_m(arm)
            self.settle(CONTROL_DT_S, arm)
            if abs(self.gripper_width_m(arm) - before) < 2e-4:
                break
        return self.sim_time_s - t0

    def settle(self, seconds: float, arm: str | None = None) -> float:
        n_sub = max(int(round(CONTROL_DT_S / self.model.opt.timestep)), 1)
        t0 = self.sim_time_s
        for _ in range(max(int(round(seconds / CONTROL_DT_S)), 1)):
            with self._lock:
                self._tick(n_sub)
                for a in [arm] if arm else self.arms:
                    self._record(a)
        return self.sim_time_s - t0

    # -- privileged ground truth (only for oracles and success predicates; never for the planner) ----------------
    def body_position(self, body: str) -> np.ndarray:
        return self.data.body(body).xpos - self.origin_m

    def body_rotation(self, body: str) -> np.ndarray:
        return self.data.body(body).xmat.reshape(3, 3).copy()

    def joint_value(self, joint: str) -> float:
        return float(self.data.joint(joint).qpos[0])

    def set_joint_value(self, joint: str, value: float) -> None:
        with self._lock:
            self.data.joint(joint).qpos[0] = value
            mujoco.mj_forward(self.model, self.data)

    def set_body_position(self, body: str, xyz) -> None:
        """Teleport a free object (tests: move an object mid-plan)."""
        with self._lock:
            adr = self.model.joint(body + "/free").qposadr[0]
            self.data.qpos[adr : adr + 3] = np.asarray(xyz, float) + self.origin_m
            self.data.qvel[self.model.joint(body + "/free").dofadr[0] :][:6] = 0
            mujoco.mj_forward(self.model, self.data)

    def body_geoms(self, body: str) -> list[int]:
        """Geom ids of a body and its sub-bodies."""
        m = self.model
        root = m.body(body).id
        ids = {b for b in range(m.nbody) if b == root or _is_descendant(m, b, root)}
        return [g for g in range(m.ngeom) if m.geom_bodyid[g] in ids]

    def _geoms_bounds(self, geoms, R_frame: np.ndarray | None = None) -> tuple[np.ndarray, np.ndarray]:
        """(min, max) of the geoms' boxes along the axes of `R_frame` (world axes when None), MuJoCo origin."""
        m, d = self.model, self.data
        Rt = np.eye(3) if R_frame is None else R_frame.T
        lo, hi = np.full(3, np.inf), np.full(3, -np.inf)
        for g in geoms:
            Rg = d.geom_xmat[g].reshape(3, 3)
            R = Rt @ Rg
            ext = np.abs(R) @ _geom_half_extent(m, g)
            # a mesh's box is its own (its vertices' bounds), which need not be centred on the geom's frame
            off = m.geom_aabb[g][:3] if m.geom_type[g] == mujoco.mjtGeom.mjGEOM_MESH else np.zeros(3)
            c = Rt @ (d.geom_xpos[g] + Rg @ off)
            lo, hi = np.minimum(lo, c - ext), np.maximum(hi, c + ext)
        return lo, hi

    def body_aabb(self, body: str) -> tuple[np.ndarray, np.ndarray]:
        """World-frame axis-aligned bounds (min, max) of a body and its sub-bodies' geoms."""
        lo, hi = self._geoms_bounds(self.body_geoms(body))
        return lo - self.origin_m, hi - self.origin_m

    def body_extent_m(self, body: str, yaw_rad: float) -> np.ndarray:
        """Full size of the body's geoms along the axes of a frame turned `yaw_rad` about world z: the object's
        own length and width, which a world-axis box overstates once it is turned."""
        c, s = np.cos(yaw_rad), np.sin(yaw_rad)
        lo, hi = self._geoms_bounds(self.body_geoms(body), np.array([[c, -s, 0], [s, c, 0], [0, 0, 1.0]]))
        return hi - lo

    def body_id(self, body: str) -> int:
        return self.model.body(body).id

    def bodies_in_contact(self, body_a: str, body_b: str) -> bool:
        m, d = self.model, self.data
        a, b = m.body(body_a).id, m.body(body_b).id
        for i in range(d.ncon):
            c = d.contact[i]
            pair = (m.geom_bodyid[c.geom1], m.geom_bodyid[c.geom2])
            if pair == (a, b) or pair == (b, a):
                return True
        return False

    # -- cameras -----------------------------------------------------------------------------------------------
    def render(self, camera: str, width: int = 640, height: int = 480):
        from .cameras import render_frame

        with self._lock:  # no physics step while the frame is drawn
            t0 = time.perf_counter()
            try:
                return self.on_render_thread(render_frame, self, camera, width, height)
            finally:
                self.wall_s["rendering"] += time.perf_counter() - t0

    def on_render_thread(self, fn: Callable, *args):
        """Run `fn(*args)` on this world's one rendering thread. An EGL context is current on one thread at a
        time, and arms in parallel branches (or a capture monitor) may ask for frames from different threads."""
        if self._render_pool is None:
            from concurrent.futures import ThreadPoolExecutor

            self._render_pool = ThreadPoolExecutor(1, thread_name_prefix="render")
        return self._render_pool.submit(fn, *args).result()

    def close(self) -> None:
        if self._render_pool is not None:
            if self.renderer is not None:
                self._render_pool.submit(self.renderer.close).result()
            self._render_pool.shutdown(wait=True)
            self._render_pool = None
        elif self.renderer is not None:
            self.renderer.close()
        self.renderer = None


def _subtree(m: mujoco.MjModel, root: int) -> set[int]:
    return {b for b in range(m.nbody) if b == root or _is_descendant(m, b, root)}


def _is_descendant(m: mujoco.MjModel, b: int, root: int) -> bool:
    while b > 0:
        b = m.body_parentid[b]
        if b == root:
            return True
    return False


def _geom_half_extent(m: mujoco.MjModel, g: int) -> np.ndarray:
    s = m.geom_size[g]
    t = m.geom_type[g]
    if t == mujoco.mjtGeom.mjGEOM_BOX:
        return s.copy()
    if t == mujoco.mjtGeom.mjGEOM_CYLINDER:
        return np.array([s[0], s[0], s[1]])
    if t == mujoco.mjtGeom.mjGEOM_SPHERE:
        return np.full(3, s[0])
    if t == mujoco.mjtGeom.mjGEOM_CAPSULE:
        return np.array([s[0], s[0], s[1] + s[0]])
    if t == mujoco.mjtGeom.mjGEOM_MESH:
        return m.geom_aabb[g][3:].copy()  # the mesh's vertex bounds in the geom frame, tighter than its sphere
    return np.full(3, m.geom_rbound[g])
