"""One small annotated detection image per grounding and camera (first detection, re-detections on recovery,
each adaptive-prompt resolution), so the console shows what perception saw at the time of each grounding.

The resolver keeps only its latest frames and its latest detection per label, so the sink looks at it as each
grounding is made (the resolver's `grounding_listeners`) and after every event (`watch`): a grounding made since
the last look is kept with the frames and detections it used, if the resolver still holds them (the frames'
simulated time equals the grounding's). `save` draws and writes the images kept since the last save, so a live
trial's images are on disk (and in its record) while it runs; each image is written once.
"""

from __future__ import annotations

import hashlib
import threading
from pathlib import Path
from typing import Any

import numpy as np

MAX_WIDTH_PX = 320  # stored images are reduced to this width (JPEG): a stack_two trial keeps ~10 of ~15 kB
JPEG_QUALITY = 80


class GroundingImages:
    """Collects, per grounding index, the (frame, kept detection, keypoint) of each camera it looked through."""

    def __init__(self) -> None:
        self._seen = 0
        self._kept: list[tuple[int, dict, dict[str, tuple[Any, Any]]]] = []  # (index, record, camera -> (frame, det))
        self._saved: list[dict] = []  # the artifact entries written so far, in order
        self._lock = threading.Lock()  # parallel branches publish events from their own threads

    def watch(self, resolver: Any) -> None:
        """Keep the groundings made since the last call (cheap when there are none)."""
        groundings = getattr(resolver, "groundings", None) or []
        with self._lock:
            if len(groundings) <= self._seen:
                return
            frames = dict(getattr(resolver, "frames", {}) or {})
            detections = getattr(resolver, "detections", {}) or {}
            for i in range(self._seen, len(groundings)):
                g = groundings[i]
                t = g.get("t_sim_s")
                per_cam: dict[str, tuple[Any, Any]] = {}
                for cam, sel in (g.get("cameras") or {}).items():
                    frame = frames.get(cam)
                    if frame is None or t is None or abs(float(getattr(frame, "sim_time_s", -1.0)) - t) > 1e-9:
                        continue  # the resolver has captured new frames since: this grounding's are gone
                    det = detections.get(cam, {}).get(g["label"]) if sel.get("chosen") else None
                    per_cam[cam] = (frame, det)
                if per_cam:
                    self._kept.append((i, g, per_cam))
            self._seen = len(groundings)

    @property
    def entries(self) -> list[dict]:
        """Every artifact entry written so far (by all `save` calls), in grounding order."""
        with self._lock:
            return list(self._saved)

    def save(self, directory: Path) -> list[dict]:
        """Draw, annotate and write the images kept since the last save; their artifact entries (kind
        `grounding`, with the grounding's index in the trial's groundings, its label, simulated time and
        camera). Each kept grounding is written once: a second save without new groundings returns []."""
        import cv2

        from ..perception import Keypoint
        from ..perception.annotate import annotate

        out: list[dict] = []
        with self._lock:
            kept, self._kept = list(self._kept), []
        for i, g, per_cam in kept:
            kp = g.get("keypoint")
            keypoints = (
                {g["label"]: Keypoint(g["label"], np.array(kp["position_m"]), np.array(kp["extent_m"]))} if kp else {}
            )
            for cam, (frame, det) in per_cam.items():
                img = annotate(frame, [det] if det is not None else [], keypoints)
                h, w = img.shape[:2]
                if w > MAX_WIDTH_PX:
                    img = cv2.resize(img, (MAX_WIDTH_PX, round(h * MAX_WIDTH_PX / w)), interpolation=cv2.INTER_AREA)
                ok, buf = cv2.imencode(
                    ".jpg", cv2.cvtColor(img, cv2.COLOR_RGB2BGR), [cv2.IMWRITE_JPEG_QUALITY, JPEG_QUALITY]
                )
                if not ok:
                    raise ValueError(f"could not encode grounding {i} ({cam}) as JPEG")
                data = buf.tobytes()
                name = f"grounding-{i:03d}-{cam.replace('/', '-')}"
                directory.mkdir(parents=True, exist_ok=True)
                path = directory / f"{name}.jpg"
                path.write_bytes(data)
                out.append(
                    {
                        "name": name,
                        "path": str(path),
                        "sha256": hashlib.sha256(data).hexdigest(),
                        "kind": "grounding",
                        "grounding": i,
                        "label": g["label"],
                        "t_sim_s": g.get("t_sim_s"),
                        "camera": cam,
                    }
                )
        with self._lock:
            self._saved += out
            self._saved.sort(key=lambda a: a["grounding"])
        return out


__all__ = ["GroundingImages", "MAX_WIDTH_PX"]
