"""Export recorded trials as a LeRobot dataset (format v3.0), with SPARK's labels on top.

Layout written (what LeRobot's loader reads):
  meta/info.json                   codebase_version v3.0, fps, features (dtype / shape / names, video info), paths
  meta/tasks.parquet               task (index) -> task_index
  meta/subtasks.parquet            subtask (index) -> subtask_index: one per "primitive(label)", plus "idle"
  meta/episodes/chunk-000/file-000.parquet   per episode: length, data and video locations, stats, spark/* labels
  meta/stats.json                  per-feature min / max / mean / std / count (images per channel, in [0, 1])
  data/chunk-XXX/file-XXX.parquet  timestamp, frame_index, episode_index, index, task_index, subtask_index,
                                   observation.state, observation.velocity, observation.ee_pose, action,
                                   spark.node_path, spark.primitive, spark.label
  videos/<key>/chunk-XXX/file-XXX.mp4   episodes concatenated (packets copied, no re-encoding)
Episodes go into one data file and one video file per camera until the size limits, then the next file.
Only trials recorded with capture on have frames; by default only successful ones are exported.
"""

from __future__ import annotations

import json
import time
from dataclasses import dataclass, field
from datetime import datetime
from pathlib import Path
from typing import Any, cast

import numpy as np

from .store import TraceStore

CODEBASE_VERSION = "v3.0"
DATA_PATH = "data/chunk-{chunk_index:03d}/file-{file_index:03d}.parquet"
VIDEO_PATH = "videos/{video_key}/chunk-{chunk_index:03d}/file-{file_index:03d}.mp4"
NUMERIC = {
    "observation.state": "state",
    "observation.velocity": "velocity",
    "observation.ee_pose": "ee_pose",
    "action": "action",
}
IDLE = "idle"  # frames where no primitive runs (before the first, between nodes, the final settle)


class ExportError(ValueError):
    """Nothing to export, or trials that cannot share one dataset; the message says which and why."""


@dataclass(frozen=True)
class ExportFilter:
    tasks: tuple[str, ...] = ()
    trial_ids: tuple[str, ...] = ()
    batch: str | None = None
    success_only: bool = True  # verified demonstrations only, unless asked otherwise
    since: datetime | None = None
    until: datetime | None = None


@dataclass
class ExportReport:
    out_dir: str
    episodes: int = 0
    frames: int = 0
    bytes_on_disk: int = 0
    wall_time_s: float = 0.0
    data_files: int = 0
    video_files: int = 0
    skipped: list[dict] = field(default_factory=list)  # {id, reason}


def export_lerobot(
    store: TraceStore,
    out_dir: str | Path,
    flt: ExportFilter = ExportFilter(),
    *,
    data_file_mb: float = 100.0,
    video_file_mb: float = 200.0,
    chunks_size: int = 1000,
    robot_type: str = "panda",
) -> ExportReport:
    t0 = time.perf_counter()
    out = Path(out_dir)
    if out.exists() and any(out.iterdir()):
        raise ExportError(f"{out} is not empty: export into a new directory (nothing is overwritten)")
    report = ExportReport(str(out))
    episodes = []
    for trial in _select(store, flt):
        ep = _episode_source(trial)
        if isinstance(ep, str):
            report.skipped.append({"id": trial["id"], "reason": ep})
        else:
            episodes.append(ep)
    if not episodes:
        why = "; ".join(f"{s['id']}: {s['reason']}" for s in report.skipped[:5]) or "no trial matches the filters"
        raise ExportError(f"nothing to export ({why})")
    _check_compatible(episodes)
    out.mkdir(parents=True, exist_ok=True)
    meta0 = episodes[0]["meta"]
    fps = float(meta0["fps"])
    video_keys = [f"observation.images.{k}" for k in meta0["cameras"]]
    tasks = list(dict.fromkeys(ep["trial"]["instruction"] for ep in episodes))
    subtasks = [IDLE] + sorted({s for ep in episodes for s in ep["subtask"] if s != IDLE})
    task_index = {t: i for i, t in enumerate(tasks)}
    subtask_index = {s: i for i, s in enumerate(subtasks)}

    data = _ChunkedParquet(out, data_file_mb, chunks_size)
    videos = {key: _ChunkedVideo(out, key, video_file_mb, chunks_size, fps) for key in video_keys}
    episode_rows, index = [], 0
    for e, ep in enumerate(episodes):
        n, trial = ep["n"], ep["trial"]
        frame_rows = {
            "timestamp": (np.arange(n) / fps).astype(np.float32),
            "frame_index": np.arange(n, dtype=np.int64),
            "episode_index": np.full(n, e, np.int64),
            "index": np.arange(index, index + n, dtype=np.int64),
            "task_index": np.full(n, task_index[trial["instruction"]], np.int64),
            "subtask_index": np.asarray([subtask_index[s] for s in ep["subtask"]], np.int64),
            **{feat: ep["arrays"][key] for feat, key in NUMERIC.items()},
            "spark.node_path": ep["node_path"],
            "spark.primitive": ep["primitive"],
            "spark.label": ep["label"],
        }
        chunk, file = data.add(frame_rows)
        row = {
            "episode_index": e,
            "tasks": [trial["instruction"]],
            "length": n,
            "data/chunk_index": chunk,
            "data/file_index": file,
            "dataset_from_index": index,
            "dataset_to_index": index + n,
            "meta/episodes/chunk_index": 0,
            "meta/episodes/file_index": 0,
        }
        for key in video_keys:
            cam = key.split(".", 2)[2]
            vchunk, vfile, t_from = videos[key].add(ep["videos"][cam], n)
            row |= {
                f"videos/{key}/chunk_index": vchunk,
                f"videos/{key}/file_index": vfile,
                f"videos/{key}/from_timestamp": t_from,
                f"videos/{key}/to_timestamp": t_from + n / fps,
            }
        for feat, values in frame_rows.items():
            if not feat.startswith("spark."):
                for stat, v in _stats(values).items():
                    row[f"stats/{feat}/{stat}"] = v
        for key in video_keys:
            for stat, v in ep["meta"]["image_stats"][key.split(".", 2)[2]].items():
                row[f"stats/{key}/{stat}"] = v
        row |= {
            "spark/trial_id": trial["id"],
            "spark/instruction": trial["instruction"],
            "spark/plan_text": trial["plan_text"],
            "spark/outcome": trial["outcome"],
            "spark/success": bool(trial["success"]),
            "spark/failure": trial["failure"] or "",
            "spark/failed_node": trial["failed_node"] or "",
            "spark/reason": trial["reason"] or "",
            "spark/planner": trial["planner"],
            "spark/segmenter": trial["segmenter"],
            "spark/protocol": json.dumps(trial["protocol"]),
            "spark/segments": json.dumps(ep["segments"]),
        }
        episode_rows.append(row)
        index += n
    data.close()
    for v in videos.values():
        v.close()

    features = _features(meta0, video_keys, fps)
    _write_parquet(out / "meta/episodes/chunk-000/file-000.parquet", _columns(episode_rows))
    _write_indexed(out / "meta/tasks.parquet", "task", tasks)
    _write_indexed(out / "meta/subtasks.parquet", "subtask", subtasks)
    (out / "meta/stats.json").write_text(json.dumps(_dataset_stats(episode_rows, features), indent=2))
    info = {
        "codebase_version": CODEBASE_VERSION,
        "robot_type": robot_type,
        "total_episodes": len(episodes),
        "total_frames": index,
        "total_tasks": len(tasks),
        "chunks_size": chunks_size,
        "data_files_size_in_mb": data_file_mb,
        "video_files_size_in_mb": video_file_mb,
        "fps": fps,
        "splits": {"train": f"0:{len(episodes)}"},
        "data_path": DATA_PATH,
        "video_path": VIDEO_PATH,
        "features": features,
        "spark": {
            "labels": "per frame: spark.node_path / spark.primitive / spark.label (the primitive running "
            "when the frame was taken, its node in the behavior tree, its object label) and "
            "subtask_index; per episode: spark/* columns of meta/episodes",
            "success_only": flt.success_only,
            "protocols": sorted(
                {f"planner={ep['trial']['planner']}, segmenter={ep['trial']['segmenter']}" for ep in episodes}
            ),
        },
    }
    (out / "meta/info.json").write_text(json.dumps(info, indent=2))
    report.episodes, report.frames = len(episodes), index
    report.data_files, report.video_files = data.files, sum(v.files for v in videos.values())
    report.bytes_on_disk = sum(p.stat().st_size for p in out.rglob("*") if p.is_file())
    report.wall_time_s = round(time.perf_counter() - t0, 3)
    return report


# -- selection and per-episode sources --------------------------------------------------------------------------


def _select(store: TraceStore, flt: ExportFilter) -> list[dict]:
    ids = store.trial_ids(
        tasks=flt.tasks,
        ids=flt.trial_ids,
        batch=flt.batch,
        success=True if flt.success_only else None,
        since=flt.since,
        until=flt.until,
    )
    return [t for t in (store.get_trial(i) for i in ids) if t is not None and t["status"] == "done"]


def _episode_source(trial: dict) -> dict | str:
    """Everything one episode needs, or why the trial cannot be one."""
    arts = {a["name"]: a for a in trial.get("artifacts") or []}
    if "episode.npz" not in arts:
        return "recorded without capture (no frames): run it with capture on"
    path = Path(arts["episode.npz"]["path"])
    if not path.exists():
        return f"its capture file {path} is missing"
    z = np.load(path)
    meta = json.loads(str(z["meta"]))
    n = len(z["t_s"])
    if n == 0:
        return "its capture has no frames"
    videos = {}
    for cam in meta["cameras"]:
        v = arts.get(f"video-{cam}.mp4")
        if v is None or not Path(v["path"]).exists():
            return f"its {cam} video is missing"
        videos[cam] = Path(v["path"])
    node_path = [str(p) for p in z["node_path"]]
    primitive = [str(p) for p in z["primitive"]]
    from ..grammar import parse_plan

    plan = parse_plan(trial["plan_text"]) if trial.get("plan_text") else None
    label = [_labels(plan, p) for p in node_path]
    subtask = [
        IDLE
        if not p
        else ";".join(
            f"{pr}({lb})" if lb else pr
            for pr, lb in zip(prim.split(";"), (lab.split(";") if lab else [""] * len(p.split(";"))))
        )
        for p, prim, lab in zip(node_path, primitive, label)
    ]
    return {
        "trial": trial,
        "meta": meta,
        "n": n,
        "videos": videos,
        "node_path": node_path,
        "primitive": primitive,
        "label": label,
        "subtask": subtask,
        "segments": _segments(node_path, primitive, label, meta["fps"]),
        "arrays": {k: z[k].astype(np.float32) for k in NUMERIC.values()},
    }


def _labels(plan, paths: str) -> str:
    """The object label(s) a node names (';' between parallel arms)."""
    from ..grammar import PrimitiveCall

    if not paths or plan is None:
        return ""
    out = []
    for path in paths.split(";"):
        try:
            node = plan.node_at(path)
        except KeyError:
            node = None
        out.append(", ".join(node.labels) if isinstance(node, PrimitiveCall) else "")
    return ";".join(out)


def _segments(node_path: list[str], primitive: list[str], label: list[str], fps: float) -> list[dict]:
    """Consecutive frames under one primitive node: {node_path, primitive, label, from_frame, to_frame (excl.)}."""
    segs: list[dict] = []
    for k, (p, pr, lb) in enumerate(zip(node_path, primitive, label)):
        if segs and segs[-1]["node_path"] == p:
            segs[-1]["to_frame"] = k + 1
        else:
            segs.append({"node_path": p, "primitive": pr or IDLE, "label": lb, "from_frame": k, "to_frame": k + 1})
    for s in segs:
        s["from_timestamp"], s["to_timestamp"] = s["from_frame"] / fps, s["to_frame"] / fps
    return segs


def _check_compatible(episodes: list[dict]) -> None:
    ref = episodes[0]
    keys = ("fps", "width", "height", "vcodec", "cameras")
    for ep in episodes[1:]:
        for k in keys:
            if ep["meta"][k] != ref["meta"][k]:
                raise ExportError(
                    f"trial {ep['trial']['id']} was captured with {k}={ep['meta'][k]!r} but "
                    f"{ref['trial']['id']} with {ref['meta'][k]!r}: one dataset needs one setting"
                )
        if ep["meta"]["names"] != ref["meta"]["names"]:
            raise ExportError(
                f"trial {ep['trial']['id']} has a different robot state layout than "
                f"{ref['trial']['id']} (another embodiment): export them separately"
            )


# -- features and statistics ------------------------------------------------------------------------------------


def _features(meta: dict, video_keys: list[str], fps: float) -> dict:
    feats: dict = {}
    for key in video_keys:
        feats[key] = {
            "dtype": "video",
            "shape": [meta["height"], meta["width"], 3],
            "names": ["height", "width", "channels"],
            "info": {
                "video.height": meta["height"],
                "video.width": meta["width"],
                "video.codec": "av1" if "av1" in meta["vcodec"] else "h264",
                "video.pix_fmt": "yuv420p",
                "video.is_depth_map": False,
                "video.fps": fps,
                "video.channels": 3,
                "has_audio": False,
            },
        }
    for feat, key in NUMERIC.items():
        feats[feat] = {"dtype": "float32", "shape": [len(meta["names"][key])], "names": meta["names"][key]}
    feats["timestamp"] = {"dtype": "float32", "shape": [1], "names": None}
    for k in ("frame_index", "episode_index", "index", "task_index", "subtask_index"):
        feats[k] = {"dtype": "int64", "shape": [1], "names": None}
    for k in ("spark.node_path", "spark.primitive", "spark.label"):
        feats[k] = {"dtype": "string", "shape": [1], "names": None}
    return feats


def _stats(values) -> dict:
    x = np.asarray(values, np.float64)
    x = x.reshape(len(x), -1)
    return {
        "min": x.min(0).tolist(),
        "max": x.max(0).tolist(),
        "mean": x.mean(0).tolist(),
        "std": x.std(0).tolist(),
        "count": [len(x)],
    }


def _dataset_stats(episode_rows: list[dict], features: dict) -> dict:
    """Per-episode statistics combined exactly (pooled mean and variance weighted by frame counts)."""
    out = {}
    for feat, spec in features.items():
        if spec["dtype"] == "string":
            continue
        eps = [
            {s: np.asarray(r[f"stats/{feat}/{s}"], np.float64) for s in ("min", "max", "mean", "std", "count")}
            for r in episode_rows
        ]
        n = np.array([float(e["count"][0]) for e in eps])
        means = np.stack([e["mean"] for e in eps])
        w = (n / n.sum()).reshape((-1,) + (1,) * (means.ndim - 1))
        mean = (w * means).sum(0)
        var = (w * (np.stack([e["std"] for e in eps]) ** 2 + (means - mean) ** 2)).sum(0)
        out[feat] = {
            "min": np.min([e["min"] for e in eps], 0).tolist(),
            "max": np.max([e["max"] for e in eps], 0).tolist(),
            "mean": mean.tolist(),
            "std": np.sqrt(var).tolist(),
            "count": [int(n.sum())],
        }
    return out


# -- writers ----------------------------------------------------------------------------------------------------


def _columns(rows: list[dict]) -> dict:
    return {k: [r.get(k) for r in rows] for k in dict.fromkeys(k for r in rows for k in r)}


def _arrow_column(values):
    import pyarrow as pa

    arr = values if isinstance(values, np.ndarray) else None
    if arr is not None and arr.ndim == 2:  # fixed-length vectors, as LeRobot's features declare them
        return pa.FixedSizeListArray.from_arrays(pa.array(arr.reshape(-1)), arr.shape[1])
    return pa.array(values if arr is None else arr)


def _write_parquet(path: Path, columns: dict) -> None:
    import pyarrow as pa
    import pyarrow.parquet as pq

    path.parent.mkdir(parents=True, exist_ok=True)
    pq.write_table(pa.table({k: _arrow_column(v) for k, v in columns.items()}), path)


def _write_indexed(path: Path, name: str, values: list[str]) -> None:
    """`name` (string) as the pandas index and `<name>_index` as the column: LeRobot's tasks.parquet layout."""
    import pyarrow as pa
    import pyarrow.parquet as pq

    table = pa.table({f"{name}_index": pa.array(range(len(values)), pa.int64()), name: pa.array(values, pa.string())})
    pandas_meta = {
        "index_columns": [name],
        "column_indexes": [],
        "columns": [
            {
                "name": f"{name}_index",
                "field_name": f"{name}_index",
                "pandas_type": "int64",
                "numpy_type": "int64",
                "metadata": None,
            },
            {"name": name, "field_name": name, "pandas_type": "unicode", "numpy_type": "object", "metadata": None},
        ],
        "creator": {"library": "spark", "version": "1"},
        "pandas_version": "2.2.0",
    }
    pq.write_table(table.replace_schema_metadata({b"pandas": json.dumps(pandas_meta).encode()}), path)


class _ChunkedParquet:
    """Frames of consecutive episodes into data files of at most ~`limit_mb` (an episode never splits)."""

    def __init__(self, root: Path, limit_mb: float, chunks_size: int):
        self.root, self.limit, self.chunks_size = root, limit_mb * 1e6, chunks_size
        self.chunk = self.file = 0
        self.pending: list[dict] = []
        self.size = 0
        self.files = 0

    def add(self, columns: dict) -> tuple[int, int]:
        nbytes = sum(v.nbytes if isinstance(v, np.ndarray) else sum(len(s) for s in v) for v in columns.values())
        if self.pending and self.size + nbytes > self.limit:
            self._flush()
            self.file += 1
            if self.file == self.chunks_size:
                self.chunk, self.file = self.chunk + 1, 0
        self.pending.append(columns)
        self.size += nbytes
        return self.chunk, self.file

    def _flush(self) -> None:
        merged = {
            k: (
                np.concatenate([p[k] for p in self.pending])
                if isinstance(self.pending[0][k], np.ndarray)
                else [x for p in self.pending for x in p[k]]
            )
            for k in self.pending[0]
        }
        _write_parquet(self.root / DATA_PATH.format(chunk_index=self.chunk, file_index=self.file), merged)
        self.pending, self.size = [], 0
        self.files += 1

    def close(self) -> None:
        if self.pending:
            self._flush()


class _ChunkedVideo:
    """Episodes' videos of one camera concatenated into MP4 files by copying packets (no re-encoding);
    a new file starts when the current one passes ~`limit_mb`."""

    def __init__(self, root: Path, key: str, limit_mb: float, chunks_size: int, fps: float):
        self.root, self.key, self.limit, self.chunks_size, self.fps = root, key, limit_mb * 1e6, chunks_size, fps
        self.chunk = self.file = 0
        self.container: Any = None  # av OutputContainer of the current file
        self.stream: Any = None
        self.frames = 0  # frames already in the current file
        self.path: Path | None = None
        self.files = 0

    def add(self, src: Path, n: int) -> tuple[int, int, float]:
        import av

        # self.path is set with self.container
        if self.container is not None and cast(Path, self.path).stat().st_size + src.stat().st_size > self.limit:
            self.close()
            self.file += 1
            if self.file == self.chunks_size:
                self.chunk, self.file = self.chunk + 1, 0
        with av.open(str(src)) as inp:
            ist = inp.streams.video[0]
            if self.container is None:
                self.path = self.root / VIDEO_PATH.format(
                    video_key=self.key, chunk_index=self.chunk, file_index=self.file
                )
                self.path.parent.mkdir(parents=True, exist_ok=True)
                self.container = av.open(str(self.path), "w")
                self.stream = self.container.add_stream_from_template(ist, opaque=True)  # copy, no codec needed
                self.frames = 0
                self.files += 1
            t_from = self.frames / self.fps
            offset = int(round(t_from / ist.time_base))  # type: ignore[operator]  # a demuxed stream has one
            copied = 0
            for packet in inp.demux(ist):
                if packet.dts is None:
                    continue  # the demuxer's end-of-stream marker
                packet.pts += offset  # type: ignore[operator]  # set whenever dts is (stream copy of an MP4)
                packet.dts += offset
                packet.stream = self.stream
                self.container.mux(packet)
                copied += 1
            if copied != n:
                raise ExportError(f"{src} holds {copied} frames but its episode has {n}")
        self.frames += n
        return self.chunk, self.file, t_from

    def close(self) -> None:
        if self.container is not None:
            self.container.close()
            self.container = None
