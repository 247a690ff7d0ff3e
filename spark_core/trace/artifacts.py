"""Trial artifacts on disk (annotated detection images), referenced from the record by path and SHA-256."""

from __future__ import annotations

import hashlib
from pathlib import Path

import cv2
import numpy as np


def file_entry(path: Path, **meta) -> dict:
    """A file already on disk as an artifact entry: {name, path, sha256, **meta}."""
    h = hashlib.sha256()
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            h.update(block)
    return {"name": Path(path).name, "path": str(path), "sha256": h.hexdigest(), **meta}


def capture_entries(capture, directory: Path) -> list[dict]:
    """Write an EpisodeCapture (training-data frames and videos) under `directory`; its artifact entries."""
    return [file_entry(path, **meta) for path, meta in capture.save(Path(directory))]


def save_png(directory: Path, name: str, rgb: np.ndarray, **meta) -> dict:
    directory.mkdir(parents=True, exist_ok=True)
    path = directory / f"{name}.png"
    ok, buf = cv2.imencode(".png", cv2.cvtColor(rgb, cv2.COLOR_RGB2BGR))
    if not ok:
        raise ValueError(f"could not encode {name} as PNG")
    data = buf.tobytes()
    path.write_bytes(data)
    return {"name": name, "path": str(path), "sha256": hashlib.sha256(data).hexdigest(), **meta}


def planner_image(rgb: np.ndarray, camera: str | None, directory: Path) -> dict:
    """The annotated image attached to the planner's BT call, byte for byte as sent (its SHA-256 equals the one
    the call's trace record names)."""
    from ..planning.llm import png_bytes

    data = png_bytes(rgb)
    directory.mkdir(parents=True, exist_ok=True)
    path = directory / "planner-input.png"
    path.write_bytes(data)
    return {
        "name": "planner-input",
        "path": str(path),
        "sha256": hashlib.sha256(data).hexdigest(),
        "kind": "planner_input",
        "camera": camera,
    }


def detection_images(resolver, directory: Path) -> list[dict]:
    """One annotated image per camera: the last frame, the chosen detection of every label, its keypoint."""
    from ..perception.annotate import annotate

    out = []
    keypoints = {}
    for g in getattr(resolver, "groundings", []):
        if g.get("keypoint"):
            from ..perception import Keypoint

            kp = g["keypoint"]
            keypoints[g["label"]] = Keypoint(g["label"], np.array(kp["position_m"]), np.array(kp["extent_m"]))
    for camera, frame in getattr(resolver, "frames", {}).items():
        dets = list(getattr(resolver, "detections", {}).get(camera, {}).values())
        name = "detections-" + camera.replace("/", "-")
        out.append(save_png(directory, name, annotate(frame, dets, keypoints), kind="detections", camera=camera))
    return out
