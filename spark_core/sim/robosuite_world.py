"""robosuite adapter: a robosuite environment's MuJoCo model and data behind our World protocol.

The executor and primitives run unchanged. What the adapter does:
- Frame: our world frame has its origin under the first robot's base on the table top, x forward, z up
  (robosuite's is the floor under the table centre). `origin_m` is where our origin sits in robosuite's.
- Arms: robosuite's Pandas have torque motors. A computed-torque joint servo (PD through the joint-space
  inertia, plus gravity, Coriolis and passive-force compensation) tracks our joint trajectories at every
  physics step, in place of robosuite's 20 Hz controllers. Nothing in the model changes but the gripper's
  force limit per grasp.
- Gripper: the two finger position actuators get +-half the commanded gap; the force limit is the model's own
  (20 N), the strongest the robosuite Panda hand can squeeze.
- TCP: robosuite's `grip_site` (0.097 m below the hand flange) with the hand's orientation, which is the frame
  our Panda kinematics end in (`robosuite_panda()`), so IK and physics agree.
- Time: we step physics directly (2 ms) instead of `env.step` (50 ms); a task's horizon of N robosuite steps is
  N / control_freq seconds of simulated time.
- Cameras: robosuite's own cameras, drawn with `mujoco.Renderer` on demand (robosuite's offscreen renderer is
  off, so no robosuite GL context exists).
"""

from __future__ import annotations

import dataclasses
from functools import lru_cache
from typing import Any

import mujoco
import numpy as np

from ..control.panda import panda
from ..control.pose import Pose
from ..control.robot import GripperSpec, RobotDescription
from .objects import ObjectSpec
from .robot_mjcf import RobotNames
from .scene import PlacedObject, Scene
from .world import MujocoWorld

ROBOSUITE_CONTROL_HZ = 20  # CaP-X runs robosuite at 20 Hz: one robosuite step is 50 ms of simulated time
GRIP_SITE_BELOW_HAND_M = 0.097  # robosuite PandaGripper: eef body (grip_site) below the hand body
WIPER_SITE_BELOW_HAND_M = 0.03  # robosuite WipingGripper: grip_site at the pad's bottom face, below the hand
SERVO_KP = 900.0  # 1/s^2: joint servo stiffness through the inertia matrix (natural frequency 30 rad/s)
SERVO_KD = 60.0  # 1/s: critically damped


def require_robosuite():
    """Import robosuite or say exactly what is missing and how to install it."""
    try:
        import robosuite
    except ImportError as e:  # the benchmark extras are not part of the console's install
        raise RuntimeError(
            "the capbench suite needs robosuite 1.4.0, which is not installed: run `make bench-deps` "
            f"(installs the pinned benchmark extras into .venv) [{e}]"
        ) from None
    return robosuite


@lru_cache(maxsize=2)
def robosuite_panda(wiper: bool = False) -> RobotDescription:
    """Our Panda (same URDF, limits and IK) ending in robosuite's grip site instead of the URDF hand TCP, with
    robosuite's rest pose and hand (80 mm stroke, 20 N force limit).

    `wiper`: robosuite's WipingGripper instead of the hand, a 12 x 5 cm pad (long side along the hand's y axis,
    where fingers would close) fixed 3 cm below the flange; the TCP is the middle of the pad's bottom face."""
    below = WIPER_SITE_BELOW_HAND_M if wiper else GRIP_SITE_BELOW_HAND_M
    extra = (
        '<link name="robosuite_grip_site"/><joint name="robosuite_grip_site_joint" type="fixed">'
        '<parent link="panda_hand"/><child link="robosuite_grip_site"/>'
        f'<origin xyz="0 0 {below}" rpy="0 0 0"/></joint>'
    )
    base = panda()
    return dataclasses.replace(
        base,
        name="panda-robosuite-wiper" if wiper else "panda-robosuite",
        tcp_frame="robosuite_grip_site",
        extra_urdf=extra,
        # robosuite's Panda.init_qpos: where every episode starts (before its initialisation noise)
        home_q_rad=np.array([0.0, np.pi / 16, 0.0, -np.pi / 2 - np.pi / 3, 0.0, np.pi - 0.2, np.pi / 4]),
        gripper=GripperSpec(
            base.gripper.finger_joints,
            max_width_m=0.08,
            closed_empty_width_m=0.004,
            max_force_n=20.0,
            finger_speed_m_s=0.1,
            grasp_depth_m=0.03,  # short fingers
            mounted_tool="wiping pad" if wiper else "",
            tool_size_m=(0.05, 0.12) if wiper else (0.0, 0.0),
        ),
        # The wrist motors give 12 N m, and robosuite's hand has a large inertia box that MuJoCo's air drag
        # acts on: the wrist joints top out near 1.5 rad/s, so trajectories are planned slower there.
        max_velocity_rad_s=(2.175, 2.175, 2.175, 2.175, 1.0, 1.0, 1.0),
        timeout_scale=1.5,
    )


@dataclasses.dataclass(frozen=True)
class RobosuiteObject:
    """An object of the robosuite task as perception sees it: label, description, and its MuJoCo body (or, for
    a part of a body such as a nut's handle, the geoms that make it)."""

    label: str
    description: str
    body: str
    geoms: tuple[str, ...] = ()  # a part: these geoms of `body` only
    category: str = "block"


def _has_fingers(m: mujoco.MjModel, i: int) -> bool:
    return mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_JOINT, f"gripper{i}_finger_joint1") >= 0


def _names(m: mujoco.MjModel, i: int) -> RobotNames:
    r, g = f"robot{i}_", f"gripper{i}_"
    bodies = tuple(m.body(b).name for b in range(m.nbody) if m.body(b).name.startswith((r, g, f"mount{i}_")))
    fingers = _has_fingers(m, i)
    return RobotNames(
        prefix=r,
        arm_joints=tuple(f"{r}joint{k}" for k in range(1, 8)),
        arm_actuators=tuple(f"{r}torq_j{k}" for k in range(1, 8)),
        finger_joints=(f"{g}finger_joint1", f"{g}finger_joint2") if fingers else (),
        gripper_actuator=f"{g}gripper_finger_joint1" if fingers else "",
        tcp_site=f"{g}grip_site",
        wrist_camera=f"{r}eye_in_hand",
        bodies=bodies,
        finger_bodies=(f"{g}leftfinger", f"{g}rightfinger") if fingers else (),
        base_body=f"{r}base",
    )


def arm_indices(n_robots: int) -> dict[str, int]:
    """Our arm names for an env's robots by index: one robot is `right`; two are `right` (robot 0) and `left`
    (robot 1). The catalog's robosuite and LIBERO embodiments list these names (spark_core/catalog.py)."""
    return {"right": 0} if n_robots == 1 else {"right": 0, "left": 1}


class RobosuiteWorld(MujocoWorld):
    """A built and reset robosuite env behind the World protocol. `arms` maps our arm names to robosuite robot
    indices (one arm: `right`; two: `right`=robot0, `left`=robot1 unless given)."""

    # Set by the suites that build such worlds, not here: LIBERO's language instruction (tasks/liberopro.py) and
    # Wipe's referee (tasks/capbench.py).
    instruction: str
    referee: Any
    # Camera frames draw their RGB only when read (sim.cameras.DeferredFrame): robosuite scenes' shaded pass is
    # most of a trial's rendering time, and the privileged segmenter reads only depth and ids.
    defer_rgb = True

    def __init__(
        self,
        env: Any,
        objects: list[RobosuiteObject],
        arms: dict[str, int] | None = None,
        seed: int = 0,
        perception_cameras: tuple[str, ...] = ("agentview", "sideview"),
    ):
        self.env = env
        m, d = env.sim.model._model, env.sim.data._data
        n_robots = len(env.robots)
        arms = arms or arm_indices(n_robots)
        table_z = _support_height(env)
        base0 = d.body(f"robot{min(arms.values())}_base").xpos.copy()
        origin = np.array([base0[0], base0[1], table_z])
        names = {a: _names(m, i) for a, i in arms.items()}
        T_world_base = {}
        for a, n in names.items():
            T = np.eye(4)
            T[:3, :3] = d.body(f"{n.prefix}link0").xmat.reshape(3, 3)
            T[:3, 3] = d.body(f"{n.prefix}link0").xpos - origin
            T_world_base[a] = T
        placed = {
            o.label: PlacedObject(
                o.label,
                ObjectSpec(o.label, o.category, o.description, 0.0, 0.0, True, _no_build),
                "",
                o.body,
                d.body(o.body).xpos - origin,
                0.0,
            )
            for o in objects
            if not o.geoms
        }
        # a part made of geoms gets a pseudo body name "<body>#<label>" that body_aabb and the cameras understand
        parts = {o.label: (f"{o.body}#{o.label}", o.description) for o in objects if o.geoms}
        cams = tuple(m.camera(c).name for c in range(m.ncam))
        # home = where the env starts the arm (robosuite's init pose plus its noise; LIBERO's own, much higher)
        robots = {
            a: dataclasses.replace(
                robosuite_panda(wiper=not _has_fingers(m, i)),
                home_q_rad=np.array([d.qpos[m.joint(j).qposadr[0]] for j in names[a].arm_joints]),
            )
            for a, i in arms.items()
        }
        scene = Scene(
            m,
            names,
            robots,
            T_world_base,
            placed,
            parts,
            cams,
            seed,
            extra={"perception_cameras": perception_cameras, "simulator": "robosuite"},
        )
        # a part's geoms with their visual twins (robosuite draws `<geom>_visual` / `<geom>_vis`, not the collider)
        self.part_geoms = {
            f"{o.body}#{o.label}": {
                m.geom(n).id
                for g in o.geoms
                for n in (g, f"{g}_visual", f"{g}_vis")
                if mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_GEOM, n) >= 0
            }
            for o in objects
            if o.geoms
        }
        m.vis.global_.offwidth, m.vis.global_.offheight = (
            max(m.vis.global_.offwidth, 640),
            max(m.vis.global_.offheight, 480),
        )
        self._forcerange0 = m.actuator_forcerange.copy()  # as built: put back when the env is handed on
        self._q_cmd: dict[str, np.ndarray] = {}
        self._qd_cmd: dict[str, np.ndarray] = {}
        super().__init__(scene, data=d, origin_m=origin)
        self._grip2 = {
            a: m.actuator(f"gripper{i}_gripper_finger_joint2").id for a, i in arms.items() if a in self._grip
        }
        self.reset()  # again, now that both finger actuators are known
        self._hand = {a: m.body(f"{n.prefix}right_hand").id for a, n in names.items()}
        self._ctrl_range = {a: m.actuator_ctrlrange[self._act[a]].T.copy() for a in self.arms}
        self._M = np.zeros((m.nv, m.nv))
        mujoco.mj_forward(m, d)

    # -- state: the env's own reset is the start state --------------------------------------------------------
    def reset(self) -> None:
        """Hold the start state: arm joints where they are, fingers at their current gap (robosuite leaves the
        finger set-points at zero, which would close an open hand during the first settle)."""
        for a in self.arms:
            self._q_cmd[a] = self.q(a)
            self._qd_cmd[a] = np.zeros(len(self._q_cmd[a]))
            if hasattr(self, "_grip2") and a in self._grip2:
                self._command_gripper(a, self.gripper_width_m(a))

    def tcp_pose(self, arm: str) -> Pose:
        """robosuite's grip site, in the hand's orientation (fingers close along the hand's y axis)."""
        return Pose(
            self.data.site_xpos[self._tcp[arm]] - self.origin_m, self.data.xmat[self._hand[arm]].reshape(3, 3).copy()
        )

    def joint_command(self, arm: str) -> np.ndarray:
        return self._q_cmd[arm].copy()

    def _command_joints(self, arm: str, q_rad: np.ndarray, qd_rad_s: np.ndarray | None = None) -> None:
        self._q_cmd[arm] = np.asarray(q_rad, float).copy()
        self._qd_cmd[arm] = np.zeros(len(q_rad)) if qd_rad_s is None else np.asarray(qd_rad_s, float).copy()

    def gripper_command_m(self, arm: str) -> float:
        if arm not in self._grip:
            return 0.0  # a mounted tool
        return float(self.data.ctrl[self._grip[arm]] - self.data.ctrl[self._grip2[arm]])

    def _command_gripper(self, arm: str, width_m: float) -> None:
        self.data.ctrl[self._grip[arm]] = width_m / 2
        self.data.ctrl[self._grip2[arm]] = -width_m / 2

    def _limit_gripper_force(self, arm: str, force_n: float) -> None:
        for g in (self._grip[arm], self._grip2[arm]):
            self.model.actuator_forcerange[g] = [-force_n, force_n]

    def _tick(self, steps: int) -> None:
        """Physics steps with the joint servo recomputed before each one (robosuite's arms are torque-driven)."""
        import time

        t0 = time.perf_counter()
        m, d = self.model, self.data
        for _ in range(steps):
            mujoco.mj_fullM(m, self._M, d.qM)
            for a in self.arms:
                dofs, q = self._dadr[a], d.qpos[self._qadr[a]]
                accel = SERVO_KP * (self._q_cmd[a] - q) + SERVO_KD * (self._qd_cmd[a] - d.qvel[dofs])
                tau = self._M[np.ix_(dofs, dofs)] @ accel + d.qfrc_bias[dofs] - d.qfrc_passive[dofs]
                lo, hi = self._ctrl_range[a]
                d.ctrl[self._act[a]] = np.clip(tau, lo, hi)
            mujoco.mj_step(m, d)
        self.wall_s["simulation"] += time.perf_counter() - t0
        for monitor in self.monitors:
            monitor(self)

    # -- privileged: parts made of some geoms of a body (a nut's handle) --------------------------------------
    def body_geoms(self, body: str) -> list[int]:
        """A part's geoms that are there now: robosuite erases a wiped Wipe marker by making its visual-only geom
        transparent, and then it is neither seen nor touched."""
        geoms = self.part_geoms.get(body)
        if geoms is None:
            return super().body_geoms(body)
        m = self.model
        return sorted(g for g in geoms if m.geom_rgba[g, 3] > 0 or m.geom_contype[g] or m.geom_conaffinity[g])

    def body_rotation(self, body: str) -> np.ndarray:
        return super().body_rotation(body.split("#")[0])  # a part turns with its body

    def close(self) -> None:
        super().close()
        # Not env.close(): robosuite's MjSim.free() ends in a full gc.collect(), 0.3-0.6 s a trial once torch and
        # the text encoder are loaded. Dropping the env's references frees the same model and data (its
        # offscreen renderer is off, so there is no GL context to release); the automatic collector takes any
        # reference cycles.
        release = getattr(self.env, "_spark_release", None)
        if release is not None and self.env.sim is not None:  # the env goes back for the task's next trial
            self.model.actuator_forcerange[:] = self._forcerange0  # grasps lowered the finger force limits
            release()
            return
        self.env._destroy_viewer()
        self.env.sim = None


def _support_height(env) -> float:
    """Height of the surface the task's objects stand on (robosuite's frame): the table top, or the floor."""
    for attr in ("table_offset",):
        if hasattr(env, attr):
            return float(np.asarray(getattr(env, attr))[2])
    if hasattr(env, "table_offsets"):  # two-arm envs
        return float(env.table_offsets[0][2])
    return 0.0  # LIBERO-Object: a floor scene


def _no_build(body, rgba):  # robosuite builds its own objects
    raise RuntimeError("robosuite objects are built by robosuite, not by the SPARK scene builder")
