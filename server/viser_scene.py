"""The live 3D view (viser): the running trial's robot links, objects and table, republished at a fixed rate,
with the keypoints perception resolved drawn as labelled markers."""

from __future__ import annotations

import contextlib
import io
import threading
import time

import mujoco
import numpy as np


class ViserScene:
    """One viser server per console. `show(world)` mirrors a world until `detach`; updates are coalesced by
    viser, so a slow browser never slows the simulation."""

    def __init__(self, host: str = "127.0.0.1", port: int = 0, rate_hz: float = 30.0):
        import viser

        with contextlib.redirect_stdout(io.StringIO()):  # viser prints a banner; the server logs its own line
            self.server = viser.ViserServer(host=host, port=port, verbose=False)
        self.host = host
        self.rate_hz = rate_hz
        self._world = None
        self._frames: dict[int, object] = {}
        self._lock = threading.Lock()
        self._stop = threading.Event()
        self.ticks = 0
        self._thread = threading.Thread(target=self._publish, name="viser-publisher", daemon=True)
        self._thread.start()

    @property
    def port(self) -> int:
        return self.server.get_port()

    def show(self, world) -> None:
        """Build the scene of `world` (bodies as frames, geoms as their children) and start mirroring it."""
        m = world.model
        scene = self.server.scene
        with self._lock:
            self._world = None
            scene.reset()
            frames: dict[int, object] = {}
            for g in range(m.ngeom):
                if m.geom_group[g] > 2 or m.geom_type[g] == mujoco.mjtGeom.mjGEOM_PLANE:
                    continue  # hidden collision-only geoms and the floor
                b = int(m.geom_bodyid[g])
                if b not in frames:
                    frames[b] = scene.add_frame(f"/world/b{b}", show_axes=False)
                self._add_geom(m, g, f"/world/b{b}/g{g}")
            self._frames = frames
            self._world = world

    def _add_geom(self, m: mujoco.MjModel, g: int, name: str) -> None:
        scene = self.server.scene
        rgba = m.geom_rgba[g]
        color = tuple(int(255 * c) for c in rgba[:3])
        pose = dict(position=m.geom_pos[g].copy(), wxyz=m.geom_quat[g].copy())
        t, size = m.geom_type[g], m.geom_size[g]
        if t == mujoco.mjtGeom.mjGEOM_BOX:
            scene.add_box(name, color=color, dimensions=2 * size, **pose)
        elif t == mujoco.mjtGeom.mjGEOM_SPHERE:
            scene.add_icosphere(name, radius=float(size[0]), color=color, **pose)
        elif t in (mujoco.mjtGeom.mjGEOM_CYLINDER, mujoco.mjtGeom.mjGEOM_CAPSULE):
            scene.add_cylinder(name, radius=float(size[0]), height=float(2 * size[1]), color=color, **pose)
        elif t == mujoco.mjtGeom.mjGEOM_MESH:
            mid = m.geom_dataid[g]
            v0, nv = m.mesh_vertadr[mid], m.mesh_vertnum[mid]
            f0, nf = m.mesh_faceadr[mid], m.mesh_facenum[mid]
            scene.add_mesh_simple(name, vertices=m.mesh_vert[v0:v0 + nv].copy(), faces=m.mesh_face[f0:f0 + nf].copy(),
                                  color=color, **pose)

    def markers(self, keypoints: dict) -> None:
        """Keypoints as small spheres with their labels (world frame)."""
        for i, (label, kp) in enumerate(keypoints.items()):
            p = np.asarray(kp.position_m, float)
            self.server.scene.add_icosphere(f"/keypoints/k{i}", radius=0.008, color=(255, 40, 200), position=p)
            self.server.scene.add_label(f"/keypoints/k{i}/label", text=label, position=p + [0, 0, 0.03])

    def detach(self, world) -> None:
        """Stop mirroring `world` (its last pose stays on screen)."""
        with self._lock:
            if self._world is world:
                self._world = None

    def _publish(self) -> None:
        period = 1.0 / self.rate_hz
        while not self._stop.is_set():
            t0 = time.monotonic()
            with self._lock:
                world = self._world
                if world is not None:
                    # No world lock: rendering for perception holds it for ~75 ms per frame and the view must not
                    # stall. A copy taken mid-step can mix two physics steps (2 ms apart): invisible on screen.
                    xpos, xquat = world.data.xpos.copy(), world.data.xquat.copy()
                    with self.server.atomic():
                        for b, frame in self._frames.items():
                            frame.position, frame.wxyz = xpos[b], xquat[b]
                    self.ticks += 1
            self._stop.wait(max(0.0, period - (time.monotonic() - t0)))

    def stop(self) -> None:
        self._stop.set()
        self._thread.join(2.0)
        with contextlib.redirect_stdout(io.StringIO()):
            self.server.stop()
            # viser's server thread prints "Server stopped" as it exits, possibly after stop() returns under
            # load: wait for it (longer than viser's own 1 s) so the message never lands after our output.
            thread = getattr(getattr(self.server, "_websock_server", None), "_server_thread", None)
            if thread is not None:
                thread.join(10.0)
