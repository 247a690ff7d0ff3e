"""SceneFeed: samples a running MuJoCo world for the 3D view on its own thread, next to the simulation
(in the trial's worker process), and hands plain-array messages to a sink (a pipe to the console, or a
ViserScene directly)."""

from __future__ import annotations

import threading
from collections.abc import Callable

import mujoco
import numpy as np

from spark_core import body_poses, visual_geoms

Sink = Callable[[str, object], None]  # (kind: scene | poses | markers | image, payload)


class SceneFeed:
    def __init__(self, world, sink: Sink, rate_hz: float = 30.0, resolver=None):
        self.world, self.sink, self.rate_hz, self.resolver = world, sink, rate_hz, resolver
        self._stop = threading.Event()
        self._thread = threading.Thread(target=self._run, name="scene-feed", daemon=True)
        self._n_groundings = 0

    def start(self) -> SceneFeed:
        self.sink("scene", visual_geoms(self.world.model))
        self._thread.start()
        return self

    def stop(self) -> None:
        self._stop.set()
        if self._thread.is_alive():
            self._thread.join(5.0)
        self._publish()  # the final state stays on screen
        self._perception(force=True)

    def _run(self) -> None:
        import time

        period = 1.0 / self.rate_hz
        due = time.monotonic() + period
        while not self._stop.wait(max(0.0, due - time.monotonic())):
            self._publish()
            self._perception()
            due = max(due + period, time.monotonic() - period)  # catch up after a stall, but never in a burst

    def _publish(self) -> None:
        w = self.world
        # No world lock: rendering for perception holds it for ~75 ms per frame and the view must not stall.
        # A copy taken mid-step can mix two physics steps (2 ms apart): invisible on screen.
        xpos, xquat = body_poses(w.model, w.data)
        xpos -= getattr(w, "origin_m", 0.0)  # bodies in the world's frame, where keypoints and targets are
        targets = {}
        for arm, pose in dict(getattr(w, "target_tcp", {})).items():
            q = np.zeros(4)
            mujoco.mju_mat2Quat(q, np.ascontiguousarray(pose.rotation).ravel())
            targets[arm] = (pose.position_m.copy(), q)
        self.sink("poses", (xpos, xquat, targets))

    def _perception(self, force: bool = False) -> None:
        """New groundings since the last look: their keypoints, and the annotated image of the camera used."""
        groundings = list(getattr(self.resolver, "groundings", []) or [])
        if len(groundings) == self._n_groundings and not (force and groundings):
            return
        self._n_groundings = len(groundings)
        kps = {g["label"]: g["keypoint"]["position_m"] for g in groundings if g.get("keypoint")}
        self.sink("markers", kps)
        try:
            img = annotated_view(self.resolver)
            if img is not None:
                self.sink("image", img)
        except Exception:
            pass


def annotated_view(resolver, width: int = 320) -> np.ndarray | None:
    """The first camera's latest frame with its detections and keypoints drawn, `width` pixels wide."""
    import cv2

    from spark_core import Keypoint, annotate

    frames = dict(getattr(resolver, "frames", {}) or {})
    if not frames:
        return None
    camera, frame = next(iter(frames.items()))
    dets = list(getattr(resolver, "detections", {}).get(camera, {}).values())
    kps = {
        g["label"]: Keypoint(g["label"], np.array(g["keypoint"]["position_m"]), np.array(g["keypoint"]["extent_m"]))
        for g in getattr(resolver, "groundings", [])
        if g.get("keypoint")
    }
    img = annotate(frame, dets, kps)
    h = int(round(img.shape[0] * width / img.shape[1]))
    return cv2.resize(img, (width, h), interpolation=cv2.INTER_AREA)
