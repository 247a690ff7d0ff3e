"""The live 3D view (viser): the trial a console page is bound to (`focus`), or else the most recently started
one, or a replay.

The view never touches a simulation: it is fed plain arrays (`VisualGeom`s once, then body poses) by a
`SceneFeed` running next to the world, in a worker process or in a replay thread. Drawn: robot links, objects
and table; the resolved keypoints as labelled markers; the TCP pose each arm is moving to; the latest annotated
detection image (masks, boxes, keypoints); the active node of the tree."""

from __future__ import annotations

import contextlib
import io
import threading
from typing import Any

import numpy as np

from spark_core import VisualGeom


class ViserScene:
    """One viser server per console. Updates are coalesced by viser, so a slow browser never slows a trial."""

    def __init__(self, host: str = "127.0.0.1", port: int = 0, rate_hz: float = 30.0, env_map: bool = False):
        """`env_map`: viser's default image-based lighting (an HDR environment map). Off: its one-time setup in the
        browser blocked software WebGL's GPU process for ~4 s after each page load (no GPU on this machine),
        and every page's frames with it; the default lights alone light the scene."""
        import viser

        with contextlib.redirect_stdout(io.StringIO()):  # viser prints a banner; the server logs its own line
            self.server = viser.ViserServer(host=host, port=port, verbose=False)
        self.host = host
        self.rate_hz = rate_hz  # what feeds are asked to publish at
        self.current: str | None = None  # key (trial id, or "replay:<id>") of what is on screen
        # The key a trial page bound the view to: while set, other feeds do not take the view (they are cached,
        # so focusing one later draws it at once). None: the most recently started trial takes the view.
        self.pinned: str | None = None
        self._feeds: dict[str, dict[str, Any]] = {}  # key -> latest scene/title/poses/markers/image of its feed
        self._markers: list[Any] = []  # keypoint spheres on screen
        self._labels: dict[str, Any] = {}  # label -> its text handle (a child of its marker)
        self._frames: dict[int, Any] = {}  # body id -> viser frame
        self._targets: dict[str, Any] = {}
        self._lock = threading.Lock()
        self.ticks = 0  # pose updates drawn
        if not env_map:
            self.server.scene.configure_environment_map(None)
        cam = self.server.initial_camera  # in front of and above the table, looking at the workspace
        cam.position, cam.look_at = (1.7, -1.1, 1.2), (0.5, 0.0, 0.25)
        gui = self.server.gui
        self._active = gui.add_markdown("**Trial:** none")
        self._image = gui.add_image(BLANK, label="detections (masks, boxes, keypoints)")
        self.image_key: str | None = None  # whose detection image is on screen (None: blank)

    @property
    def port(self) -> int:
        return self.server.get_port()

    def show(self, key: str, geoms: list[VisualGeom], title: str = "") -> None:
        """Replace the scene with `geoms` (bodies as frames, geoms as their children); `key` now owns the view."""
        scene = self.server.scene
        with self._lock:
            self.current = key
            scene.reset()
            frames: dict[int, Any] = {}
            for i, g in enumerate(geoms):
                if g.body not in frames:
                    frames[g.body] = scene.add_frame(f"/world/b{g.body}", show_axes=False)
                _add_geom(scene, g, f"/world/b{g.body}/g{i}")
            self._frames, self._targets, self._markers, self._labels = frames, {}, [], {}
            self._active.content = f"**Trial:** {title or key}"
            self._image.image = BLANK  # the previous trial's detections are not this one's
            self.image_key = None

    def update(self, key: str, xpos: np.ndarray, xquat: np.ndarray, targets: dict | None = None) -> None:
        """Body poses (world frame, wxyz) and, per arm, the (position_m, wxyz) its TCP is moving to."""
        with self._lock:
            if key != self.current:
                return
            with self.server.atomic():
                for b, frame in self._frames.items():
                    frame.position, frame.wxyz = xpos[b], xquat[b]
                for arm, (p, q) in (targets or {}).items():
                    if arm not in self._targets:
                        self._targets[arm] = self.server.scene.add_frame(
                            f"/targets/{arm}", axes_length=0.08, axes_radius=0.004
                        )
                    self._targets[arm].position, self._targets[arm].wxyz = p, q
            self.ticks += 1

    def markers(self, key: str, keypoints: dict[str, list[float]]) -> None:
        """Resolved keypoints (world frame, m) as small spheres with their labels; only those given are shown."""
        with self._lock:
            if key != self.current:
                return
            for handle in self._markers:  # only the keypoints given: a replay scrubbed back shows fewer
                handle.remove()
            self._markers, self._labels = [], {}
            for i, (label, position) in enumerate(keypoints.items()):
                p = np.asarray(position, float)
                marker = self.server.scene.add_icosphere(
                    f"/keypoints/k{i}", radius=0.008, color=(255, 40, 200), position=p
                )
                # a child of its marker: its position is in the marker's frame (3 cm above it), not the world's
                label_handle = self.server.scene.add_label(f"/keypoints/k{i}/label", text=label, position=(0, 0, 0.03))
                self._markers.append(marker)
                self._labels[label] = label_handle

    def image(self, key: str, rgb: np.ndarray | None) -> None:
        """The annotated detection image of `key`'s trial (None: blank)."""
        with self._lock:
            if key == self.current:
                self._image.image = BLANK if rgb is None else rgb
                self.image_key = None if rgb is None else key

    def active(self, key: str, text: str) -> None:
        with self._lock:
            if key == self.current:
                self._active.content = text

    def sink(self, key: str, title: str = ""):
        """A SceneFeed sink drawing into this view under `key`. The feed's first message takes the view unless a
        page pinned another key; every message is kept (latest of each kind) so `focus(key)` can draw it later."""

        def draw(kind: str, payload) -> None:
            with self._lock:
                feed = self._feeds.setdefault(key, {"title": title})
                feed[kind] = payload
                while len(self._feeds) > MAX_FEEDS:  # oldest first: dicts keep insertion order
                    self._feeds.pop(next(iter(self._feeds)))
                take = kind == "scene" and (self.pinned is None or self.pinned == key)
            if take:
                self.show(key, payload, title)
            elif kind == "poses":
                self.update(key, *payload)
            elif kind == "markers":
                self.markers(key, payload)
            elif kind == "image":
                self.image(key, payload)

        return draw

    def focus(self, key: str | None) -> bool:
        """Bind the view to `key` (a trial page opened it); None unbinds. A live feed already seen under `key` is
        drawn at once from its latest messages. Returns whether that happened."""
        with self._lock:
            self.pinned = key
            feed = dict(self._feeds.get(key or "", {}))
        if "scene" not in feed or key is None:
            return False
        self.show(key, feed["scene"], feed.get("title", ""))
        if "poses" in feed:
            self.update(key, *feed["poses"])
        if "markers" in feed:
            self.markers(key, feed["markers"])
        if "image" in feed:
            self.image(key, feed["image"])
        return True

    def stop(self) -> None:
        with contextlib.redirect_stdout(io.StringIO()):
            self.server.stop()
            # viser's server thread prints "Server stopped" as it exits, possibly after stop() returns under
            # load: wait for it (longer than viser's own 1 s) so the message never lands after our output.
            thread = getattr(getattr(self.server, "_websock_server", None), "_server_thread", None)
            if thread is not None:
                thread.join(10.0)


BLANK = np.zeros((240, 320, 3), np.uint8)
MAX_FEEDS = 8  # live feeds whose latest scene is kept for focus()


def _add_geom(scene, g: VisualGeom, name: str) -> None:
    pose = dict(position=g.position_m, wxyz=g.wxyz)
    if g.kind == "box":
        scene.add_box(name, color=g.rgb, dimensions=g.size_m, **pose)
    elif g.kind == "sphere":
        scene.add_icosphere(name, radius=float(g.size_m[0]), color=g.rgb, **pose)
    elif g.kind == "cylinder":
        scene.add_cylinder(name, radius=float(g.size_m[0]), height=float(g.size_m[1]), color=g.rgb, **pose)
    else:
        scene.add_mesh_simple(name, vertices=g.vertices_m, faces=g.faces, color=g.rgb, **pose)
