"""LeRobot v3.0 export of real captured trials, read back with pyarrow and PyAV: features match info.json,
parquet and video frame counts agree, timestamps run at the declared fps, statistics are exact, and every
frame's primitive label lines up with the trial's own event timestamps."""

import json

import av
import numpy as np
import pyarrow.parquet as pq
import pytest

from spark_core.sim.capture import CaptureConfig
from spark_core.trace import TraceStore
from spark_core.trace.lerobot import ExportError, ExportFilter, export_lerobot
from spark_core.trace.sink import StoreSink
from spark_core.trial import TrialConfig, run_trial

FAILING = (
    "task: miss\ntree: {type: sequence, children: [{primitive: pick, params: {keypoint_label: purple giraffe}}]}\n"
)


@pytest.fixture(scope="module")
def recorded(tmp_path_factory):
    root = tmp_path_factory.mktemp("export")
    store = TraceStore(f"sqlite:///{root / 't.db'}")
    cfg = CaptureConfig(fps=10, width=128, height=128)
    sinks = [StoreSink(store, root / "art")]
    ok = [
        run_trial(TrialConfig(t, segmenter="privileged-keypoints", seed=s, capture=cfg), sinks)
        for t, s in (("lift_block", 0), ("stack_two", 1))
    ]
    bad = run_trial(
        TrialConfig("lift_block", plan_text=FAILING, segmenter="privileged-keypoints", seed=2, capture=cfg), sinks
    )
    run_trial(TrialConfig("lift_block", segmenter="privileged-keypoints", seed=3), sinks)  # not captured
    assert [o.success for o in ok] == [True, True] and bad.success is False
    return store, root


def _read(out):
    info = json.loads((out / "meta/info.json").read_text())
    data = pq.read_table(out / "data/chunk-000/file-000.parquet")
    eps = pq.read_table(out / "meta/episodes/chunk-000/file-000.parquet").to_pylist()
    return info, data, eps


def test_export_reads_back_with_matching_features_frames_and_timestamps(recorded, tmp_path):
    store, _ = recorded
    out = tmp_path / "ds"
    report = export_lerobot(store, out)
    info, data, eps = _read(out)
    assert report.episodes == 2 and len(report.skipped) == 1  # the failure is filtered out before the uncaptured one
    assert "without capture" in report.skipped[0]["reason"]
    assert info["codebase_version"] == "v3.0" and info["total_episodes"] == 2 and info["fps"] == 10
    assert info["total_frames"] == data.num_rows == sum(e["length"] for e in eps)
    for name, feat in info["features"].items():
        if feat["dtype"] == "video":
            continue
        col = data.schema.field(name).type
        if feat["dtype"] == "float32" and feat["shape"] != [1]:
            assert (
                col.list_size == feat["shape"][0]
                and str(col.value_type) == "float"
                and len(feat["names"]) == col.list_size
            )
        elif feat["dtype"] == "string":
            assert str(col) == "string"
        else:
            assert str(col) == {"float32": "float", "int64": "int64"}[feat["dtype"]], name
    rows = data.to_pydict()
    for e in eps:
        sl = slice(e["dataset_from_index"], e["dataset_to_index"])
        ts = np.array(rows["timestamp"][sl])
        assert np.allclose(np.diff(ts), 1 / info["fps"], atol=1e-6) and ts[0] == 0
        assert rows["frame_index"][sl] == list(range(e["length"]))
        assert set(rows["episode_index"][sl]) == {e["episode_index"]}
        assert e["spark/success"] is True and e["spark/plan_text"].startswith("task:")
    for key in (k for k, f in info["features"].items() if f["dtype"] == "video"):
        path = out / info["video_path"].format(video_key=key, chunk_index=0, file_index=0)
        with av.open(str(path)) as c:
            frames = list(c.decode(c.streams.video[0]))
        assert len(frames) == data.num_rows  # every parquet frame has its video frame
        assert (frames[0].height, frames[0].width, 3) == tuple(info["features"][key]["shape"])
        times = np.array([f.time for f in frames])
        assert np.all(np.diff(times) > 0)
        for e in eps:  # each episode's video span holds exactly its frames, at the declared fps
            lo, hi = e[f"videos/{key}/from_timestamp"], e[f"videos/{key}/to_timestamp"]
            inside = times[(times >= lo - 1e-6) & (times < hi - 1e-6)]
            assert len(inside) == e["length"] and np.allclose(np.diff(inside), 0.1, atol=1e-3)
    tasks = pq.read_table(out / "meta/tasks.parquet").to_pydict()
    assert sorted(tasks["task"]) == sorted({e["tasks"][0] for e in eps}) and tasks["task_index"] == [0, 1]
    with pytest.raises(ExportError, match="not empty"):
        export_lerobot(store, out)


def test_stats_are_exact_on_one_episode_and_pooled_over_several(recorded, tmp_path):
    store, _ = recorded
    one = store.trial_ids(tasks=("stack_two",), success=True)
    export_lerobot(store, tmp_path / "one", ExportFilter(trial_ids=tuple(one)))
    stats = json.loads((tmp_path / "one/meta/stats.json").read_text())
    _, data, _ = _read(tmp_path / "one")
    state = np.array(data.column("observation.state").to_pylist(), np.float64)
    assert np.allclose(stats["observation.state"]["mean"], state.mean(0), atol=1e-6)
    assert np.allclose(stats["observation.state"]["std"], state.std(0), atol=1e-6)
    assert np.allclose(stats["observation.state"]["min"], state.min(0)) and stats["observation.state"]["count"] == [
        len(state)
    ]
    img = np.array(stats["observation.images.agentview"]["mean"])
    assert img.shape == (3, 1, 1) and np.all((img > 0) & (img < 1))
    export_lerobot(store, tmp_path / "all")
    pooled = json.loads((tmp_path / "all/meta/stats.json").read_text())
    _, data, _ = _read(tmp_path / "all")
    action = np.array(data.column("action").to_pylist(), np.float64)
    assert np.allclose(pooled["action"]["mean"], action.mean(0), atol=1e-6)
    assert np.allclose(pooled["action"]["std"], action.std(0), atol=1e-6)


def test_frame_labels_line_up_with_the_trial_events(recorded, tmp_path):
    store, _ = recorded
    out = tmp_path / "labels"
    export_lerobot(store, out)
    _, data, eps = _read(out)
    rows = data.to_pydict()
    subtasks = pq.read_table(out / "meta/subtasks.parquet").to_pydict()["subtask"]
    for e in eps:
        trial = store.get_trial(e["spark/trial_id"])
        npz = np.load(next(a["path"] for a in trial["artifacts"] if a["name"] == "episode.npz"))
        spans = {}
        for ev in trial["events"]:
            if ev["kind"] == "started" and "primitive" in ev["detail"]:
                spans[ev["node_path"]] = [ev["t"], None]
            elif ev["kind"] in ("succeeded", "failed") and ev["node_path"] in spans:
                spans[ev["node_path"]][1] = ev["t"]
        sl = slice(e["dataset_from_index"], e["dataset_to_index"])
        labelled = 0
        for k, (path, prim, label, sub) in enumerate(
            zip(
                rows["spark.node_path"][sl],
                rows["spark.primitive"][sl],
                rows["spark.label"][sl],
                rows["subtask_index"][sl],
            )
        ):
            t = npz["clock_s"][k]  # when the frame was taken, on the event bus's clock
            if path:
                start, end = spans[path]
                assert start <= t <= end, (path, start, t, end)  # taken while that primitive ran
                node = trial["plan_tree"]["tree"]["children"][int(path.split("[")[1].rstrip("]"))]
                assert prim == node["primitive"]
                assert subtasks[sub] == (f"{prim}({label})" if label else prim)
                labelled += 1
            else:
                assert not any(s <= t < f for s, f in spans.values()) and subtasks[sub] == "idle"
        assert labelled > e["length"] / 2
        assert "red block" in rows["spark.label"][sl]  # move_to_keypoint / pick name their object
        segments = json.loads(e["spark/segments"])
        assert segments[0]["from_frame"] == 0 and segments[-1]["to_frame"] == e["length"]


def test_nothing_to_export_says_why(recorded, tmp_path):
    store, _ = recorded
    with pytest.raises(ExportError, match="no trial matches"):
        export_lerobot(store, tmp_path / "x", ExportFilter(tasks=("open_drawer",)))
    with pytest.raises(ExportError, match="without capture"):
        export_lerobot(
            store,
            tmp_path / "y",
            ExportFilter(trial_ids=tuple(store.trial_ids(tasks=("lift_block",), success=True)[-1:])),
        )
    failed = export_lerobot(store, tmp_path / "z", ExportFilter(success_only=False))
    assert failed.episodes == 3
