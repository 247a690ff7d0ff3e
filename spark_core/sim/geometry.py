"""What a viewer needs to draw a MuJoCo scene without MuJoCo: the visual geoms (shape, size, colour, pose in
their body frame) once, then body poses (world frame) per frame. Plain arrays, so it pickles across processes."""

from __future__ import annotations

from dataclasses import dataclass
from typing import cast

import mujoco
import numpy as np


@dataclass(frozen=True)
class VisualGeom:
    body: int  # MuJoCo body id; the geom is drawn in this body's frame
    kind: str  # box | sphere | cylinder | mesh
    rgb: tuple[int, int, int]
    position_m: np.ndarray  # in the body frame
    wxyz: np.ndarray  # orientation in the body frame
    size_m: np.ndarray  # box: full extents; sphere: (radius,); cylinder/capsule: (radius, height)
    vertices_m: np.ndarray | None = None  # mesh only, in the geom frame
    faces: np.ndarray | None = None


_KINDS = {
    mujoco.mjtGeom.mjGEOM_BOX: "box",
    mujoco.mjtGeom.mjGEOM_SPHERE: "sphere",
    mujoco.mjtGeom.mjGEOM_CYLINDER: "cylinder",
    mujoco.mjtGeom.mjGEOM_CAPSULE: "cylinder",
    mujoco.mjtGeom.mjGEOM_MESH: "mesh",
}


def visual_geoms(m: mujoco.MjModel) -> list[VisualGeom]:
    """Every drawable geom: hidden collision-only geoms (group > 2) and the floor plane are skipped."""
    out = []
    for g in range(m.ngeom):
        kind = _KINDS.get(int(m.geom_type[g]))
        if kind is None or m.geom_group[g] > 2:
            continue
        size = m.geom_size[g]
        verts = faces = None
        if kind == "box":
            size = 2 * size
        elif kind == "sphere":
            size = size[:1]
        elif kind == "cylinder":
            size = np.array([size[0], 2 * size[1]])
        else:
            mid = m.geom_dataid[g]
            v0, nv, f0, nf = m.mesh_vertadr[mid], m.mesh_vertnum[mid], m.mesh_faceadr[mid], m.mesh_facenum[mid]
            verts, faces = m.mesh_vert[v0 : v0 + nv].copy(), m.mesh_face[f0 : f0 + nf].copy()
        out.append(
            VisualGeom(
                int(m.geom_bodyid[g]),
                kind,
                cast("tuple[int, int, int]", tuple(int(255 * c) for c in m.geom_rgba[g][:3])),
                m.geom_pos[g].copy(),
                m.geom_quat[g].copy(),
                np.array(size, float),
                verts,
                faces,
            )
        )
    return out


def body_poses(m: mujoco.MjModel, d: mujoco.MjData, qpos: np.ndarray | None = None) -> tuple[np.ndarray, np.ndarray]:
    """(xpos (nbody, 3) m, xquat (nbody, 4) wxyz) in the world frame; with `qpos`, forward kinematics of that
    state on `d` first (replay)."""
    if qpos is not None:
        d.qpos[:] = qpos
        mujoco.mj_kinematics(m, d)
    return d.xpos.copy(), d.xquat.copy()
