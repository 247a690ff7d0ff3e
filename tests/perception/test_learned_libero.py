"""The learned segmenter's LIBERO data: scenes from LIBERO's own placement samplers (never an evaluation init
state), labels consistent with the categories, grounding of LIBERO prompts, the head grown for new categories,
and training on builtin + LIBERO data together (one step: a code-path check, not training)."""

from __future__ import annotations

import numpy as np
import pytest
import torch

from spark_cli import main
from spark_core.perception.learned.categories import CATEGORIES, CATEGORY_INDEX, COLOUR_INDEX, category_of_libero
from spark_core.perception.learned.segmenter import LearnedSegmenter


@pytest.mark.parametrize(
    "prompt,category,colours",
    [
        ("black bowl", "bowl", {"black"}),
        ("akita black bowl 2", "bowl", {"black"}),
        ("alphabet soup", "alphabet soup", set()),
        ("cream cheese", "cream cheese", set()),  # "cream" names the cheese: no colour filter
        ("the orange juice", "orange juice", set()),
        ("ketchup", "ketchup", set()),
        ("tomato sauce", "tomato sauce", set()),
        ("wine bottle", "wine bottle", set()),
        ("wine rack", "wine rack", set()),
        ("ramekin", "ramekin", set()),
        ("cookie box", "cookie box", set()),
        ("wooden cabinet", "cabinet", set()),
        ("flat stove", "stove", set()),
        ("plate", "plate", set()),
        ("basket", "basket", set()),
        ("orange block", "block", {"orange"}),
    ],
)
def test_libero_prompts_ground_to_their_category(prompt, category, colours):
    cats, wanted = LearnedSegmenter().ground(prompt)
    assert CATEGORIES[max(cats, key=cats.__getitem__)].name == category
    assert wanted == colours


def test_a_compound_noun_grounds_to_its_head_not_its_modifier():
    """ "cabinet drawer layer" (an adaptive variant of "drawer middle layer") is a drawer: "layer" names a region
    of the noun before it, which is the head; the cabinet it modifies must not tie with it."""
    cats, _ = LearnedSegmenter().ground("cabinet drawer layer")
    assert [CATEGORIES[c].name for c in cats] == ["drawer"]
    # an unknown last word is still the head: a grip of the drawer is its handle, not the drawer
    cats, _ = LearnedSegmenter().ground("cabinet drawer grip")
    assert "drawer handle" in [CATEGORIES[c].name for c in cats]


def test_libero_labels_map_to_categories():
    assert CATEGORIES[category_of_libero("akita black bowl 2")].name == "bowl"
    assert CATEGORIES[category_of_libero("glazed rim porcelain ramekin")].name == "ramekin"
    assert CATEGORIES[category_of_libero("wooden cabinet top drawer handle")].name == "drawer handle"
    assert CATEGORIES[category_of_libero("wooden cabinet top drawer")].name == "drawer"
    with pytest.raises(KeyError, match="moka pot"):
        category_of_libero("moka pot")


def test_older_weights_get_a_head_for_the_new_categories():
    """Weights saved before categories were appended keep their rows; boundary and colour rows move down."""
    from spark_core.perception.learned.train import expand_categories

    n_old, n_new, n_col = 23, len(CATEGORIES), 12
    w = torch.randn(n_old + 1 + n_col, 16, 1, 1)
    b = torch.randn(n_old + 1 + n_col)
    out = expand_categories({"head.weight": w, "head.bias": b}, n_old, n_new)
    assert out["head.weight"].shape[0] == n_new + 1 + n_col
    assert torch.equal(out["head.weight"][:n_old], w[:n_old])
    assert torch.equal(out["head.weight"][n_new:], w[n_old:])
    assert torch.equal(out["head.bias"][n_new:], b[n_old:])
    assert (out["head.bias"][n_old:n_new] < b[:n_old].max()).all()


def test_older_weights_never_predict_a_category_appended_after_them(tmp_path):
    """Loaded for inference, weights saved with fewer categories predict none of the appended ones (their new head
    rows are untrained); loaded to fine-tune (--init), every row trains."""
    from spark_core.perception.frame import CameraFrame
    from spark_core.perception.learned.model import SegNet
    from spark_core.perception.learned.train import load_net, save

    n_old = CATEGORIES.index(next(c for c in CATEGORIES if c.name == "pot"))
    net = SegNet(widths=(8, 8, 8, 8), n_categories=n_old)
    path = tmp_path / "old.pt"
    save(net, path, {})
    loaded = load_net(path)
    assert loaded.n_trained == n_old and loaded.n_categories == len(CATEGORIES)
    with torch.no_grad():  # an appended category's row made to win everywhere, were it not masked
        loaded.head.bias[n_old : len(CATEGORIES)] = 50.0
    seg = LearnedSegmenter(path)
    from spark_core.perception.learned import segmenter as segmenter_module

    segmenter_module._NETS[str(path)] = loaded
    rng = np.random.default_rng(0)
    frame = CameraFrame("agentview", rng.integers(0, 255, (96, 128, 3), np.uint8), np.ones((96, 128), np.float32),
                        np.eye(3), np.eye(4))  # fmt: skip
    cat = seg.predict(frame)[0]
    assert cat.max() < n_old
    loaded.n_trained = loaded.n_categories  # as after fine-tuning (train.train with --init)
    assert seg.predict(frame)[0].max() >= n_old
    save(loaded, tmp_path / "grown.pt", {})  # the file saved after fine-tuning predicts every category it saved
    assert load_net(tmp_path / "grown.pt").n_trained == len(CATEGORIES)


@pytest.fixture
def no_init_states(monkeypatch):
    """Any read of an evaluation init state (LIBERO-PRO's files or the env's set_init_state) fails the test."""
    pytest.importorskip("libero")
    from spark_core.sim import libero_envs

    libero_envs._configure()  # LIBERO's config file first: importing its envs otherwise asks on stdin

    def refuse(*_a, **_k):
        raise AssertionError("the LIBERO data path read an evaluation init state")

    monkeypatch.setattr(libero_envs, "init_states", refuse)
    monkeypatch.setattr(libero_envs, "_init_states_cached", refuse)
    monkeypatch.setattr(torch, "load", refuse)  # init files are torch-saved
    from libero.libero.envs.env_wrapper import ControlEnv

    monkeypatch.setattr(ControlEnv, "set_init_state", refuse, raising=False)


def test_libero_scenes_come_from_the_samplers_seeded(no_init_states):
    """Same seed, same placement; another seed moves objects (LIBERO's samplers, not a stored state)."""
    from spark_core.perception.learned.libero_data import LiberoScenes, libero_tasks

    task = libero_tasks()[0]
    scenes = LiberoScenes(perturb=False)
    try:

        def positions(seed):
            w = scenes.scene(seed, task)
            return np.array([w.data.body(o.body).xpos.copy() for o in w.scene.objects.values()])

        a, b, c = positions(912_001), positions(912_001), positions(912_002)
    finally:
        scenes.close()
    np.testing.assert_allclose(a, b, atol=1e-6)
    assert np.abs(a - c).max() > 1e-3


def test_libero_dataset_labels_are_consistent(tmp_path, no_init_states):
    """One rendered LIBERO scene: every instance is one object category, drawers and handles labelled on the
    cabinet, colours supervised only where the name says one (the black bowls)."""
    from spark_core.perception.learned.dataset import generate

    r = generate(tmp_path, 1, 912_003, ("agentview",), source="libero", log=lambda s: None)
    d = dict(np.load(r["path"]))
    assert d["rgb"].shape[1:] == (240, 320, 3) and len(d["rgb"]) == 2
    cat, inst, col = d["category"], d["instance"], d["colour"]
    things = np.array([c.thing for c in CATEGORIES])
    assert things[cat[inst > 0]].all()  # instances only on objects
    assert not inst[~things[cat]].any()  # and every object pixel has one
    for i in np.unique(inst[inst > 0]):
        assert len(np.unique(cat[inst == i])) == 1
    seen = {CATEGORIES[c].name for c in np.unique(cat)}
    assert {"table", "bowl", "plate", "ramekin", "cookie box"} <= seen, seen
    assert set(np.unique(col[col > 0])) <= {COLOUR_INDEX["black"]}
    assert (cat[col > 0] == CATEGORY_INDEX["bowl"]).all()


def test_train_on_builtin_and_libero_together(tmp_path, capsys):
    """`spark perception dataset --source libero` and `train --data A B`: each dataset keeps its own validation
    crops (one step, a code-path check)."""
    pytest.importorskip("libero")
    lib, built, weights = tmp_path / "libero", tmp_path / "builtin", tmp_path / "w.pt"
    assert main(["perception", "dataset", "--source", "libero", "--out", str(lib), "--scenes", "1",
                 "--seed", "912004", "--cameras", "agentview"]) == 0  # fmt: skip
    assert main(["perception", "dataset", "--out", str(built), "--scenes", "1", "--cameras", "agentview"]) == 0
    capsys.readouterr()
    args = ["perception", "train", "--data", str(built), str(lib), "--out", str(weights), "--steps", "1"]
    assert main([*args, "--batch", "2", "--crop", "128", "128", "--threads", "1"]) == 0
    meta = torch.load(weights, weights_only=True)["meta"]
    assert set(meta["val_pixel_iou"]) == {"builtin", "libero"}


def test_dataset_refuses_an_unknown_source(tmp_path):
    from spark_core.perception.learned.dataset import generate

    with pytest.raises(ValueError, match="unknown dataset source 'nowhere'"):
        generate(tmp_path, 1, source="nowhere")


def test_libero_objects_resolve_from_cameras_alone():
    """A LIBERO-Object scene never trained on (LIBERO's samplers, a seed of the development range) seen only
    through frames stripped of ids, the world out of reach: the basket the task names resolves onto the true
    basket (checked afterwards against the privileged pose)."""
    pytest.importorskip("libero")
    from spark_core.perception.learned.libero_data import LIBERO_DEV_SEED0, LiberoScenes, libero_tasks
    from spark_core.perception.privileged import PrivilegedResolver
    from spark_core.perception.resolver import PerceptionResolver
    from tests.perception.test_learned import CamerasOnly

    k = next(i for i, t in enumerate(libero_tasks()) if t.cell == "libero_object_swap")
    scenes = LiberoScenes()
    try:
        world = scenes.scene(LIBERO_DEV_SEED0 + 10 * k + 1)
        proxy = CamerasOnly(world)
        kp = PerceptionResolver(proxy, LearnedSegmenter(), cameras=("agentview", "frontview")).resolve("basket")
        assert kp.source == "learned"
        assert np.linalg.norm(kp.position_m - PrivilegedResolver(world).resolve("basket").position_m) < 0.03
    finally:
        scenes.close()


def test_libero_bench_scenes_are_held_out():
    """The perception bench's LIBERO scenes: two tasks per cell, seeds outside the training range, each seed a
    scene of the task it is listed under (nothing is built here)."""
    pytest.importorskip("libero")
    from spark_core.bench.perception_bench import _scene_worlds
    from spark_core.perception.learned.libero_data import LIBERO_TRAIN_SEED0, task_of_seed

    scenes = _scene_worlds("libero", 2)
    cells = [name.split(":")[0] for name, _, _ in scenes]
    assert {c: cells.count(c) for c in cells} == {c: 4 for c in set(cells)} and len(set(cells)) == 6
    for name, seed, _ in scenes:
        assert 1000 <= seed < LIBERO_TRAIN_SEED0
        assert task_of_seed(seed).name == name


def test_a_later_seed_round_of_bench_scenes_is_new_and_still_held_out():
    """`spark bench perception --seed 1`: every suite's scenes move to seeds round 0 never used, still outside the
    training ranges and, for LIBERO, still scenes of the task they are listed under; more scenes per task than a
    round holds are refused instead of running into the next round."""
    pytest.importorskip("libero")
    from spark_core.bench.perception_bench import _scene_worlds
    from spark_core.perception.learned.dataset import TRAIN_SEED0
    from spark_core.perception.learned.libero_data import LIBERO_TRAIN_SEED0, task_of_seed

    for suite, top in (("builtin", TRAIN_SEED0), ("random", TRAIN_SEED0), ("libero", LIBERO_TRAIN_SEED0)):
        first = {seed for _, seed, _ in _scene_worlds(suite, 3)}
        later = _scene_worlds(suite, 3, round_=1)
        assert later and not first & {seed for _, seed, _ in later}
        assert all(seed < top for _, seed, _ in later)
    for name, seed, _ in _scene_worlds("libero", 3, round_=1):
        assert task_of_seed(seed).name == name
    with pytest.raises(ValueError, match="overrun"):
        _scene_worlds("libero", 11)
