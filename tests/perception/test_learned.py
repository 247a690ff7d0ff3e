"""The `learned` segmenter: camera-only (never reads simulator state), grounding, catalog and factory, and the
`spark perception` commands on a tiny dataset (a code-path check, not training)."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from spark_cli import main
from spark_core.catalog import SEGMENTERS, catalog_json
from spark_core.perception.factory import make_segmenter
from spark_core.perception.learned.categories import CATEGORIES
from spark_core.perception.learned.segmenter import LearnedSegmenter, default_weights
from spark_core.perception.privileged import PrivilegedResolver
from spark_core.perception.resolver import PerceptionResolver
from spark_core.sim.tasks import BUILTIN


class CamerasOnly:
    """A world seen only through its cameras: frames stripped of ids and labels; any other attribute (state,
    scene, object names, poses) raises, so a segmenter that reached for simulator state would fail."""

    def __init__(self, world):
        object.__setattr__(self, "_world", world)

    def render(self, camera: str, width: int = 640, height: int = 480):
        frame = object.__getattribute__(self, "_world").render(camera, width, height)
        return dataclasses.replace(frame, object_ids=None, labels={})

    @property
    def sim_time_s(self) -> float:
        return object.__getattribute__(self, "_world").sim_time_s

    def __getattr__(self, name):
        raise AssertionError(f"the learned segmenter's path reached for world.{name}: simulator state")


@pytest.fixture(scope="module")
def stack_world():
    w = BUILTIN["stack_three"].make_world(900_100)
    yield w
    w.close()


def test_catalog_lists_learned_camera_only():
    assert SEGMENTERS["learned"].privileged is False
    assert SEGMENTERS["learned"].cameras is True
    assert any(s["name"] == "learned" and not s["privileged"] for s in catalog_json()["segmenters"])


def test_factory_builds_it_without_touching_the_world():
    seg = make_segmenter("learned", CamerasOnly(None))
    assert isinstance(seg, LearnedSegmenter)
    assert (seg.name, seg.privileged) == ("learned", False)


@pytest.mark.parametrize(
    "prompt,category,colours",
    [
        ("crimson cube", "block", {"red"}),
        ("the small blue block", "block", {"blue"}),
        ("coffee mug", "mug", set()),
        ("the drawer handle", "drawer handle", set()),
        ("the drawer", "drawer", set()),
        ("the stove", "stove", set()),
        ("white dial on the stove", "knob", {"white"}),
        ("wicker basket", "basket", set()),
        ("the green target area", "zone", {"green"}),
        ("yellow plastic tray", "tray", {"yellow"}),
        ("kitchen sponge", "sponge", set()),
        ("black bowl 2", "bowl", {"black"}),
        ("the red wooden cube", "block", {"red"}),
    ],
)
def test_grounding_picks_the_category_and_colour(prompt, category, colours):
    cats, wanted = LearnedSegmenter().ground(prompt)
    best = max(cats, key=cats.__getitem__)
    assert CATEGORIES[best].name == category
    assert wanted == colours


def test_unrelated_prompt_grounds_to_nothing():
    assert LearnedSegmenter().ground("a giraffe in the savanna")[0] == {}


def test_resolves_from_cameras_alone(stack_world):
    """Frames with object_ids=None and labels={}, the world out of reach: masks still come back and each
    block's keypoint lands on the true block (checked afterwards against the privileged pose)."""
    proxy = CamerasOnly(stack_world)
    frame = proxy.render("agentview")
    assert frame.object_ids is None and frame.labels == {}
    seg = LearnedSegmenter()
    dets = seg.segment(frame, ["red block", "the blocks"])
    assert dets and all(d.mask.shape == frame.shape and d.mask.any() and not d.privileged for d in dets)
    resolver = PerceptionResolver(proxy, seg, cameras=("agentview", "side"))
    truth = PrivilegedResolver(stack_world)
    for label in ("red block", "green block", "blue block"):
        kp = resolver.resolve(label)
        assert kp.source == "learned"
        assert np.linalg.norm(kp.position_m - truth.resolve(label).position_m) < 0.02, label


def test_shipped_weights_are_small():
    assert default_weights().is_file()
    assert default_weights().stat().st_size < 10_000_000


def test_dataset_and_train_commands_run_one_step(tmp_path, capsys):
    """The data and training commands end to end on one scene and one step (a code-path check)."""
    data, weights = tmp_path / "data", tmp_path / "w.pt"
    assert main(["perception", "dataset", "--out", str(data), "--scenes", "1", "--cameras", "agentview"]) == 0
    assert list(data.glob("shard_*.npz")) and not list(data.glob("partial_*"))  # written whole, then renamed
    args = ["perception", "train", "--data", str(data), "--out", str(weights), "--steps", "1", "--batch", "2"]
    assert main([*args, "--crop", "128", "128"]) == 0
    assert weights.is_file()
    frame = BUILTIN["lift_block"].make_world(900_101)
    try:
        f = dataclasses.replace(frame.render("agentview", 160, 128), object_ids=None, labels={})
    finally:
        frame.close()
    LearnedSegmenter(weights).segment(f, ["red block"])  # the freshly written weights load and run


def test_commands_refuse_bad_input(tmp_path, capsys):
    assert main(["perception", "train", "--data", str(tmp_path), "--out", str(tmp_path / "w.pt")]) == 2
    assert "no dataset shards" in capsys.readouterr().err
    assert main(["perception", "train", "--data", str(tmp_path), "--out", "w.pt", "--crop", "100", "64"]) == 2
    assert "--crop" in capsys.readouterr().err
    assert main(["perception", "dataset", "--out", str(tmp_path), "--scenes", "0"]) == 2
    assert "--scenes" in capsys.readouterr().err


def test_the_instance_cache_never_answers_for_a_new_frame_that_reuses_a_freed_frames_id():
    """The cache is keyed by the RGB array's id, camera and sim time; a new frame's array can get the id of a
    freed one (a new world at time 0, in the perception bench's loop it gave a red block's keypoint 40 cm off).
    An entry answers only for the very array it was computed from."""
    from spark_core.perception.frame import CameraFrame

    seg = LearnedSegmenter()
    rgb = np.zeros((48, 64, 3), np.uint8)
    frame = CameraFrame("agentview", rgb, np.ones((48, 64), np.float32), np.eye(3), np.eye(4))
    stale, own = ["instances of another frame"], ["instances of this frame"]
    key = (id(rgb), "agentview", 0.0)

    class Recomputed(Exception):
        pass

    def predict(_frame):
        raise Recomputed

    seg.predict = predict  # type: ignore[method-assign]
    seg._cache[key] = (np.zeros_like(rgb), stale)  # a different array that once had this id
    with pytest.raises(Recomputed):
        seg.instances(frame)
    seg._cache[key] = (rgb, own)
    assert seg.instances(frame) is own


def test_predict_gives_the_whole_frame_softmax_on_object_pixels(stack_world):
    """`predict` computes category probabilities only where the category is an object (every reader looks there
    alone): there they equal the softmax over the whole frame's logits, elsewhere they are 0, and the category is
    the softmax's argmax everywhere."""
    import torch

    from spark_core.perception.frame import CameraFrame
    from spark_core.perception.learned.frozen import frozen_forward
    from spark_core.perception.learned.model import network_input, shrink
    from spark_core.perception.learned.segmenter import _net

    seg = LearnedSegmenter()
    f = stack_world.render("agentview", 640, 480)
    frame = CameraFrame("agentview", f.rgb, f.depth_m, f.K, f.T_world_camera)
    cat, prob, _bnd, _col, _depth, probs = seg.predict(frame)
    net = _net(seg.weights)
    rgb, depth = shrink(frame.rgb, np.nan_to_num(frame.depth_m.astype(np.float32), nan=0.0, posinf=10.0), 2)
    with torch.no_grad():
        x = network_input(torch.from_numpy(rgb[None]), torch.from_numpy(depth[None]))
        logits = net.split(frozen_forward(net, x))[0]
    logits[:, net.n_trained :] = -torch.inf
    full = torch.softmax(logits[0].permute(1, 2, 0), -1).numpy()
    thing = np.array([c.thing for c in CATEGORIES])[cat]
    assert 0 < thing.mean() < 1  # both kinds of pixel are in the frame
    np.testing.assert_array_equal(cat, full.argmax(-1))
    np.testing.assert_allclose(probs[thing], full[thing], atol=1e-6)
    assert not probs[~thing].any() and not prob[~thing].any()
    np.testing.assert_allclose(prob[thing], full.max(-1)[thing], atol=1e-6)


def test_the_camera_only_segmenter_is_the_default_of_the_catalog_the_api_and_the_cli(monkeypatch, tmp_path):
    """A trial nobody chose a segmenter for perceives through the cameras (`learned`), not the oracle: the
    catalog says so (the console's form selects it), and so do a trial config, an API request, `spark run`, `spark
    plan` and `spark bench`."""
    from server.api.batches import BatchCreate
    from server.api.models import TrialCreate
    from spark_cli import _apply_config, build_parser
    from spark_core import TrialConfig

    cat = catalog_json(with_tasks=False)
    assert cat["default_segmenter"] == "learned"
    assert not next(s for s in cat["segmenters"] if s["name"] == cat["default_segmenter"])["privileged"]
    assert TrialConfig("lift_block").segmenter == "learned"
    assert TrialCreate(task="lift_block").segmenter == "learned"
    assert BatchCreate(suite="builtin", trials=1).segmenter == "learned"
    monkeypatch.delenv("SPARK_CONFIG", raising=False)
    monkeypatch.chdir(tmp_path)  # no spark.yaml: no operator settings
    for argv in (["run", "lift_block"], ["plan", "--task", "lift_block", "lift the red block"], ["bench", "builtin"]):
        args = build_parser().parse_args(argv)
        _apply_config(args)
        assert args.segmenter == "learned", argv
