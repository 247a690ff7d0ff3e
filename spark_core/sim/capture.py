"""Episode capture for training data: robot state, the commanded action and camera images sampled every
1/fps of simulated time, each frame labelled with the primitive running when it was taken. Only when asked
(it renders): ordinary trials keep the cheap control-rate trajectory only.

Runs as a world monitor (called every control period, under the world lock), so a frame is exactly the
state the controller saw. Labels come from the executor's events through `on_event` (plain dicts or Events)."""

from __future__ import annotations

import threading
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any, cast

import mujoco
import numpy as np

if TYPE_CHECKING:
    from av.video.stream import VideoStream


@dataclass(frozen=True)
class CaptureConfig:
    fps: float = 10.0  # frames per second of simulated time (the dataset's fps)
    width: int = 256
    height: int = 256
    cameras: tuple[str, ...] = ("agentview", "wrist")  # "wrist" = every arm's wrist camera
    vcodec: str = "libsvtav1"  # LeRobot's default (AV1); "libx264" for H.264
    shadows: bool = False  # shadow maps cost ~33 ms a 256x256 frame with software GL (5 ms without)

    def __post_init__(self):
        if not 1.0 <= self.fps <= 100.0:
            raise ValueError(f"capture fps must be in [1, 100] (the control rate), got {self.fps}")
        if not (16 <= self.width <= 1920 and 16 <= self.height <= 1080) or self.width % 8 or self.height % 8:
            raise ValueError(
                f"capture size must be multiples of 8 within 16..1920 x 16..1080, got {self.width}x{self.height}"
            )


@dataclass
class _Active:
    by_arm: dict[str, str] = field(default_factory=dict)  # arm -> node path of the primitive running on it
    primitive: dict[str, str] = field(default_factory=dict)  # node path -> primitive name


class EpisodeCapture:
    """Attach with `world.monitors.append(capture)`; feed labels with `bus.subscribe(capture.on_event)`."""

    def __init__(self, world, config: CaptureConfig = CaptureConfig(), clock: Callable[[], float] | None = None):
        self.world, self.config = world, config
        self.clock = clock or time.monotonic  # the event bus's clock, so frames and events share a time axis
        self.arms: tuple[str, ...] = tuple(world.arms)
        self.cameras = _resolve_cameras(world, config.cameras)  # feature key -> MuJoCo camera name
        self.rows: list[dict] = []
        self.images: dict[str, list[np.ndarray]] = {k: [] for k in self.cameras}
        self._renderer: mujoco.Renderer | None = None
        self._active = _Active()
        self._lock = threading.Lock()
        self._t0 = world.sim_time_s  # scenes settle before a trial starts: frame k is due at t0 + k / fps
        self._k = 0

    # -- labels -------------------------------------------------------------------------------------------------
    def on_event(self, ev) -> None:
        d = ev if isinstance(ev, dict) else ev.to_dict()
        detail, path = d.get("detail") or {}, d["node_path"]
        with self._lock:
            if d["kind"] == "started" and "primitive" in detail:  # composite nodes are not labels
                self._active.by_arm[detail.get("arm", "right")] = path
                self._active.primitive[path] = detail["primitive"]
            elif d["kind"] in ("succeeded", "failed"):
                for arm in [a for a, p in self._active.by_arm.items() if p == path]:
                    del self._active.by_arm[arm]

    # -- sampling -----------------------------------------------------------------------------------------------
    def __call__(self, world) -> None:
        if world.sim_time_s + 1e-9 >= self._t0 + self._k / self.config.fps:
            self.sample()

    def sample(self) -> None:
        w = self.world
        with self._lock:  # the label and the clock together: a frame is never labelled with a node that ended
            clock_s = self.clock()
            paths = [self._active.by_arm[a] for a in self.arms if a in self._active.by_arm]
            prims = [self._active.primitive[p] for p in paths]
        state, vel, ee, action = [], [], [], []
        for arm in self.arms:
            pose = w.tcp_pose(arm)
            quat = np.zeros(4)
            mujoco.mju_mat2Quat(quat, np.ascontiguousarray(pose.rotation).ravel())
            state += [*w.q(arm), w.gripper_width_m(arm)]
            vel += list(w.qd(arm))
            ee += [*pose.position_m, *quat]
            action += [*w.joint_command(arm), w.gripper_command_m(arm)]
        self.rows.append(
            {
                "t_s": w.sim_time_s,
                "clock_s": clock_s,
                "state": state,
                "velocity": vel,
                "ee_pose": ee,
                "action": action,
                "node_path": ";".join(paths),
                "primitive": ";".join(prims),
            }
        )
        for key, cam in self.cameras.items():
            self.images[key].append(w.on_render_thread(self._draw, cam))
        self._k += 1

    def _draw(self, camera: str) -> np.ndarray:
        """On the world's render thread (which owns the GL context)."""
        if self._renderer is None:
            self._renderer = mujoco.Renderer(self.world.model, self.config.height, self.config.width)
        self._renderer.update_scene(self.world.data, camera=camera)
        self._renderer.scene.flags[mujoco.mjtRndFlag.mjRND_SHADOW] = self.config.shadows
        return self._renderer.render().copy()

    def names(self) -> dict[str, list[str]]:
        """Per-dimension names of the numeric features (arm-prefixed when there are several arms)."""
        pre = (lambda a: f"{a}_") if len(self.arms) > 1 else (lambda a: "")
        out: dict[str, list[str]] = {"state": [], "velocity": [], "ee_pose": [], "action": []}
        for arm in self.arms:
            joints = [j.split("/")[-1] for j in self.world.scene.robot_descriptions[arm].arm_joints]
            out["state"] += [pre(arm) + j for j in joints] + [pre(arm) + "gripper_width_m"]
            out["velocity"] += [pre(arm) + j + "_vel" for j in joints]
            out["ee_pose"] += [pre(arm) + k for k in ("x_m", "y_m", "z_m", "qw", "qx", "qy", "qz")]
            out["action"] += [pre(arm) + j + "_target" for j in joints] + [pre(arm) + "gripper_width_cmd_m"]
        return out

    # -- storage ------------------------------------------------------------------------------------------------
    def save(self, directory: Path) -> list[tuple[Path, dict]]:
        """episode.npz (numeric rows, labels, per-camera image statistics) and one video per camera; returns
        (path, description) pairs for the trial record (`trace.artifacts.capture_entries`)."""
        import json

        directory = Path(directory)
        directory.mkdir(parents=True, exist_ok=True)
        if self._renderer is not None:
            self.world.on_render_thread(self._renderer.close)
            self._renderer = None
        n = len(self.rows)
        arrays: dict[str, Any] = {
            k: np.asarray([r[k] for r in self.rows], np.float32).reshape(n, -1)
            for k in ("state", "velocity", "ee_pose", "action")
        }
        meta = {
            "fps": self.config.fps,
            "width": self.config.width,
            "height": self.config.height,
            "vcodec": self.config.vcodec,
            "shadows": self.config.shadows,
            "cameras": self.cameras,
            "arms": list(self.arms),
            "names": self.names(),
            "image_stats": {k: _image_stats(v) for k, v in self.images.items()},
        }
        npz = directory / "episode.npz"
        np.savez_compressed(
            npz,
            t_s=np.asarray([r["t_s"] for r in self.rows], np.float64),
            clock_s=np.asarray([r["clock_s"] for r in self.rows], np.float64),
            node_path=np.asarray([r["node_path"] for r in self.rows], dtype=str),
            primitive=np.asarray([r["primitive"] for r in self.rows], dtype=str),
            meta=np.asarray(json.dumps(meta)),
            **arrays,
        )
        out = [(npz, {"kind": "episode", "frames": n, "fps": self.config.fps})]
        for key, frames in self.images.items():
            path = directory / f"video-{key}.mp4"
            encode_video(frames, path, self.config.fps, self.config.vcodec)
            out.append((path, {"kind": "video", "camera": key, "frames": len(frames)}))
        return out


def _resolve_cameras(world, wanted: tuple[str, ...]) -> dict[str, str]:
    have = tuple(world.scene.cameras)
    out: dict[str, str] = {}
    for name in wanted:
        if name == "wrist":
            wrists = [c for c in have if c.endswith("wrist")]
            for c in wrists:
                out["wrist" if len(wrists) == 1 else c.replace("/", "_")] = c
        elif name in have:
            out[name] = name
        else:
            raise ValueError(f"no camera {name!r} in this scene; cameras: {', '.join(have)} (or 'wrist')")
    return out


def _image_stats(frames: list[np.ndarray]) -> dict:
    """Per-channel min / max / mean / std / count over every pixel of every frame, in [0, 1] (LeRobot's layout
    for image features: shape (3, 1, 1)). Exact, from each channel's 256-bin histogram (fast on uint8)."""
    if not frames:
        return {}
    x = np.stack(frames).reshape(-1, 3)
    levels = np.arange(256) / 255.0
    stats: dict[str, list] = {"min": [], "max": [], "mean": [], "std": []}
    for c in range(3):
        hist = np.bincount(x[:, c], minlength=256).astype(np.float64)
        p = hist / hist.sum()
        mean = float(p @ levels)
        present = np.nonzero(hist)[0]
        stats["min"].append([[float(levels[present[0]])]])
        stats["max"].append([[float(levels[present[-1]])]])
        stats["mean"].append([[mean]])
        stats["std"].append([[float(np.sqrt(max(p @ (levels - mean) ** 2, 0.0)))]])
    return {**stats, "count": [len(frames)]}


def encode_video(frames: list[np.ndarray], path: Path, fps: float, vcodec: str = "libsvtav1") -> None:
    """RGB frames -> MP4 (yuv420p, a keyframe every 2 frames as LeRobot writes them, for fast random access)."""
    import os
    from fractions import Fraction

    import av

    os.environ.setdefault("SVT_LOG", "1")  # SVT-AV1: errors only
    rate = Fraction(fps).limit_denominator(1000)
    with av.open(str(path), "w") as out:
        stream = cast("VideoStream", out.add_stream(vcodec, rate=rate))  # vcodec names a video codec
        h, w = frames[0].shape[:2] if frames else (16, 16)
        stream.width, stream.height, stream.pix_fmt = w, h, "yuv420p"
        stream.options = {"g": "2", "crf": "30"} if "av1" in vcodec else {"g": "2", "crf": "23", "preset": "veryfast"}
        for img in frames:
            for packet in stream.encode(av.VideoFrame.from_ndarray(img, format="rgb24")):
                out.mux(packet)
        for packet in stream.encode():
            out.mux(packet)
