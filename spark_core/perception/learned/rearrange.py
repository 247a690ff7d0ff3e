"""Position changes for LIBERO training scenes, drawn from the scene seed: two movable objects trade places (the
kind of change LIBERO-PRO's swap cells make) and a movable object is set on top of another object (a bowl on the
stove, on the cabinet, on a cookie box). LIBERO's own placement samplers put each object in its BDDL region, so
without this the network never sees a bowl standing on a raised support at the back of the table, which is where
LIBERO-PRO's spatial cells put them. The targets are random points, never an evaluation init state.

TRAINING ONLY: works on the simulator's state (free joints, geoms); the segmenter never imports this.
"""

from __future__ import annotations

from dataclasses import dataclass

import mujoco
import numpy as np

SWAP_P = 0.4  # a scene gets a swap of two movable objects
STACK_P = 0.6  # a scene gets one movable object set on top of another object
STACK_WEIGHT = {"bowl": 4.0, "plate": 2.0}  # labels holding these words are chosen this much more often to move
PARK_Z_M = 10.0  # objects being moved wait here, far above the ray casts
RAY_FROM_Z_M = 3.0  # ray casts start here, below the parked objects, above everything on the table
DROP_M = 0.01  # a moved object is let go this far above the surface found under it
TRIES = 12


@dataclass(frozen=True)
class Movable:
    label: str
    body: int  # the object's root body (it carries the free joint)
    qadr: int  # qpos address of the free joint (x, y, z, quaternion)
    dadr: int  # qvel address


def movables(world) -> list[Movable]:
    """The scene's objects that sit on a free joint (LIBERO's fixtures - cabinet, stove, rack - do not)."""
    m = world.model
    out = []
    for label, obj in world.scene.objects.items():
        b = m.body(obj.body).id
        for j in range(m.njnt):
            if m.jnt_bodyid[j] == b and m.jnt_type[j] == mujoco.mjtJoint.mjJNT_FREE:
                out.append(Movable(label, b, int(m.jnt_qposadr[j]), int(m.jnt_dofadr[j])))
    return out


def _subtree(m: mujoco.MjModel, root: int) -> np.ndarray:
    bodies = [root]
    for b in range(root + 1, m.nbody):
        if m.body_parentid[b] in bodies:
            bodies.append(b)
    return np.isin(m.geom_bodyid, bodies)


def world_box(m: mujoco.MjModel, d: mujoco.MjData, geoms: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(low, high) corners (m, world frame) of the axis-aligned box around the given geoms."""
    ids = np.flatnonzero(geoms)
    if not len(ids):
        raise ValueError("no geoms")
    c = m.geom_aabb[ids, :3]
    h = m.geom_aabb[ids, 3:]
    rot = d.geom_xmat[ids].reshape(-1, 3, 3)
    centre = d.geom_xpos[ids] + np.einsum("nij,nj->ni", rot, c)
    half = np.einsum("nij,nj->ni", np.abs(rot), h)
    return (centre - half).min(0), (centre + half).max(0)


def _surface_z(m: mujoco.MjModel, d: mujoco.MjData, xy: np.ndarray, solid: np.ndarray) -> float | None:
    """Height (m) of the first geom a vertical ray meets at `xy`, or None where it meets no allowed geom."""
    geomid = np.zeros(1, np.int32)
    origin = np.array([xy[0], xy[1], RAY_FROM_Z_M])
    dist = mujoco.mj_ray(m, d, origin, np.array([0.0, 0.0, -1.0]), None, 1, -1, geomid)
    if dist < 0 or not solid[geomid[0]]:
        return None
    return RAY_FROM_Z_M - float(dist)


Move = tuple[str, str, str]  # ("swap", a, b) | ("stack", object, support) | ("gave up", object, "")


def rearrange(world, rng: np.random.Generator, table_z_m: float) -> list[Move]:
    """Move objects of `world` (before it settles); returns what was done.
    A move whose target finds no surface above the table top `table_z_m` (off the table, on the robot) is
    retried elsewhere, then given up: the object goes back where it was."""
    m, d = world.model, world.data
    mov = movables(world)
    robot = np.zeros(m.ngeom, bool)
    for r in world.scene.robots.values():
        for b in r.bodies:
            robot |= _subtree(m, m.body(b).id)
    solid = ~robot
    done: list[Move] = []
    targets: dict[int, np.ndarray] = {}  # index into mov -> target xy
    if len(mov) >= 2 and rng.random() < SWAP_P:
        i, j = rng.choice(len(mov), 2, replace=False)
        targets[int(i)] = d.qpos[mov[j].qadr : mov[j].qadr + 2].copy()
        targets[int(j)] = d.qpos[mov[i].qadr : mov[i].qadr + 2].copy()
        done.append(("swap", mov[i].label, mov[j].label))
    stacked: tuple[int, str] | None = None
    if mov and rng.random() < STACK_P:
        w = np.array([max((v for k, v in STACK_WEIGHT.items() if k in o.label), default=1.0) for o in mov])
        k = int(rng.choice(len(mov), p=w / w.sum()))
        supports = [label for label in world.scene.objects if label != mov[k].label]
        if supports:
            stacked = (k, str(rng.choice(supports)))
    mujoco.mj_forward(m, d)
    boxes = {label: world_box(m, d, _subtree(m, m.body(o.body).id)) for label, o in world.scene.objects.items()}
    home = {k: d.qpos[o.qadr : o.qadr + 7].copy() for k, o in enumerate(mov)}
    bottom = {k: float(d.qpos[o.qadr + 2] - boxes[o.label][0][2]) for k, o in enumerate(mov)}
    if stacked is not None:
        k, support = stacked
        lo, hi = boxes[support]
        centre, half = (lo[:2] + hi[:2]) / 2, (hi[:2] - lo[:2]) / 2
        targets[k] = centre + rng.uniform(-0.3, 0.3, 2) * half
        done.append(("stack", mov[k].label, support))
    for n, k in enumerate(targets):  # park every mover out of the way of the rays
        d.qpos[mov[k].qadr + 2] = PARK_Z_M + n
    mujoco.mj_forward(m, d)
    for k, xy in targets.items():
        o = mov[k]
        for t in range(TRIES):
            p = xy if t == 0 else xy + rng.normal(0, 0.03, 2)
            z = _surface_z(m, d, p, solid)
            if z is not None and z > table_z_m - 0.01:
                d.qpos[o.qadr : o.qadr + 2] = p
                d.qpos[o.qadr + 2] = z + bottom[k] + DROP_M
                break
        else:
            d.qpos[o.qadr : o.qadr + 7] = home[k]
            done.append(("gave up", o.label, ""))
        d.qvel[o.dadr : o.dadr + 6] = 0.0
        mujoco.mj_forward(m, d)  # the next ray sees this object where it now is
    return done
