"""Tabletop scene builder: table, lights, cameras, robots and objects placed collision-free from a seed.

World frame: origin at the robot base on the table top (z = 0 is the table surface), x forward, y left.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import mujoco
import numpy as np

from ..control.robot import RobotDescription
from .objects import COLORS, KINDS, ObjectSpec
from .robot_mjcf import RobotNames, add_robot

TABLE_X = (0.15, 1.0)
TABLE_Y = (-0.6, 0.6)
TIMESTEP_S = 0.002
GRIPPER_CLEARANCE_M = 0.035  # free space between footprints so open fingers fit beside an object


@dataclass(frozen=True)
class ObjectRequest:
    """An object a task wants: label, kind and colour, and where it may be placed (x/y ranges in metres, yaw rad)."""

    label: str
    kind: str
    color: str
    x: tuple[float, float]
    y: tuple[float, float]
    yaw: tuple[float, float] = (0.0, 0.0)
    z: float = 0.0
    near: str | None = None  # when set, x/y are offsets from that (already placed) object's position


@dataclass(frozen=True)
class PlacedObject:
    label: str
    spec: ObjectSpec
    color: str
    body: str  # MuJoCo body name
    position_m: np.ndarray  # initial base position (world)
    yaw_rad: float

    @property
    def description(self) -> str:
        return self.spec.description


@dataclass
class Scene:
    model: mujoco.MjModel
    robots: dict[str, RobotNames]  # arm name -> names
    robot_descriptions: dict[str, RobotDescription]
    T_world_base: dict[str, np.ndarray]
    objects: dict[str, PlacedObject]
    parts: dict[str, tuple[str, str]]  # part label -> (body name, description)
    cameras: tuple[str, ...]
    seed: int
    extra: dict = field(default_factory=dict)

    def catalog(self) -> dict[str, str]:
        """label -> description for every object and labelled part: what a text prompt is grounded against."""
        out = {label: o.description for label, o in self.objects.items()}
        out.update({label: desc for label, (_, desc) in self.parts.items()})
        return out


def _look_at_quat(eye, target) -> list[float]:
    f = np.asarray(target, float) - np.asarray(eye, float)
    f /= np.linalg.norm(f)
    x = np.cross(f, [0, 0, 1.0])
    x /= np.linalg.norm(x)
    y = np.cross(-f, x)
    R = np.column_stack([x, y, -f])
    q = np.zeros(4)
    mujoco.mju_mat2Quat(q, R.flatten())
    return list(q)


def sample_placements(
    requests: list[ObjectRequest], specs: dict[str, ObjectSpec], rng: np.random.Generator, max_tries: int = 2000
) -> dict[str, tuple[np.ndarray, float]]:
    """Rejection-sample x, y, yaw per object so footprints (discs) do not overlap. Raises if impossible."""
    placed: dict[str, tuple[np.ndarray, float]] = {}
    # Most constrained first (fixtures with a fixed spot), so free objects fill in around them; objects placed
    # relative to another come after it.
    order = sorted(requests, key=lambda r: (r.near is not None, (r.x[1] - r.x[0]) * (r.y[1] - r.y[0])))
    for req in order:
        spec = specs[req.label]
        anchor = placed[req.near][0] if req.near else np.zeros(3)
        for _ in range(max_tries):
            p = anchor + np.array([rng.uniform(*req.x), rng.uniform(*req.y), req.z])
            ok = all(
                np.linalg.norm(p[:2] - q[:2]) > spec.footprint_m + specs[o].footprint_m + GRIPPER_CLEARANCE_M
                for o, (q, _) in placed.items()
                if req.z == 0.0 and q[2] == 0.0 and o != req.near
            )
            if ok:
                placed[req.label] = (p, float(rng.uniform(*req.yaw)))
                break
        else:
            raise RuntimeError(f"could not place {req.label!r} in x{req.x} y{req.y} without collisions")
    return placed


def build_scene(
    robots: dict[str, tuple[RobotDescription, np.ndarray]],
    requests: list[ObjectRequest],
    seed: int,
    render_size: tuple[int, int] = (640, 480),
) -> Scene:
    """Compile a scene: `robots` maps arm name -> (description, T_world_base)."""
    rng = np.random.default_rng(seed)
    spec = mujoco.MjSpec()
    spec.modelname = "spark_tabletop"
    spec.option.timestep = TIMESTEP_S
    spec.option.integrator = mujoco.mjtIntegrator.mjINT_IMPLICITFAST
    spec.option.cone = mujoco.mjtCone.mjCONE_ELLIPTIC
    spec.option.noslip_iterations = 3
    spec.visual.global_.offwidth, spec.visual.global_.offheight = render_size
    spec.visual.quality.shadowsize = 2048
    wb = spec.worldbody
    wb.add_light(pos=[0.5, 0.0, 1.6], dir=[0, 0, -1], diffuse=[0.7, 0.7, 0.7], castshadow=True)
    wb.add_light(pos=[1.2, 0.8, 1.2], dir=[-0.5, -0.5, -0.7], diffuse=[0.35, 0.35, 0.35], castshadow=False)
    floor = wb.add_geom(
        name="floor", type=mujoco.mjtGeom.mjGEOM_PLANE, size=[3, 3, 0.1], pos=[0, 0, -0.75], rgba=[0.35, 0.37, 0.4, 1]
    )
    floor.contype = floor.conaffinity = 1
    cx, cy = (TABLE_X[0] + TABLE_X[1]) / 2, (TABLE_Y[0] + TABLE_Y[1]) / 2
    hx, hy = (TABLE_X[1] - TABLE_X[0]) / 2, (TABLE_Y[1] - TABLE_Y[0]) / 2
    table = wb.add_geom(
        name="table",
        type=mujoco.mjtGeom.mjGEOM_BOX,
        size=[hx, hy, 0.02],
        pos=[cx, cy, -0.02],
        rgba=[0.78, 0.72, 0.62, 1],
    )
    table.friction = [1.0, 0.01, 0.001]
    wb.add_geom(type=mujoco.mjtGeom.mjGEOM_CYLINDER, size=[0.09, 0.37, 0], pos=[0, 0, -0.375], rgba=[0.3, 0.3, 0.32, 1])
    cams = {"agentview": ([1.35, 0.0, 0.95], [0.5, 0.0, 0.0]), "side": ([0.55, -1.15, 0.55], [0.55, 0.0, 0.05])}
    for name, (eye, target) in cams.items():
        wb.add_camera(name=name, pos=eye, quat=_look_at_quat(eye, target), fovy=45.0)

    robot_names: dict[str, RobotNames] = {}
    for arm, (desc, T) in robots.items():
        prefix = f"{arm}/" if len(robots) > 1 else "robot/"
        robot_names[arm] = add_robot(spec, desc, prefix, T)

    specs = {r.label: KINDS[r.kind](r.color) for r in requests}
    poses = sample_placements(requests, specs, rng)
    objects: dict[str, PlacedObject] = {}
    parts: dict[str, tuple[str, str]] = {}
    for req in requests:
        ospec = specs[req.label]
        pos, yaw = poses[req.label]
        body = wb.add_body(name=req.label, pos=list(pos), quat=[np.cos(yaw / 2), 0, 0, np.sin(yaw / 2)])
        if ospec.movable:
            body.add_freejoint(name=req.label + "/free")
        ospec.build(body, COLORS[req.color])
        objects[req.label] = PlacedObject(req.label, ospec, req.color, req.label, pos, yaw)
        for part, part_desc in ospec.parts.items():
            # "drawer handle" of "cabinet" -> label "cabinet drawer handle", body "cabinet/handle"
            parts[f"{req.label} {part}"] = (req.label + "/" + part.split()[-1], part_desc)
    model = spec.compile()
    return Scene(
        model,
        robot_names,
        {a: d for a, (d, _) in robots.items()},
        {a: T for a, (_, T) in robots.items()},
        objects,
        parts,
        tuple(list(cams) + [n.wrist_camera for n in robot_names.values()]),
        seed,
    )
