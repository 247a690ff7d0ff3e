"""The learned segmenter's CaP-Bench data: robosuite scenes reset by the envs' own samplers from seeds outside every
evaluation range, labelled per task with the existing categories (cubes are blocks of their colour, the nut a nut,
the pegs pegs), deterministic per seed, and written by `spark perception dataset --source capbench`."""

from __future__ import annotations

import numpy as np
import pytest

from spark_cli import main
from spark_core.perception.learned import capbench_data as cb
from spark_core.perception.learned.categories import CATEGORIES, CATEGORY_INDEX, COLOUR_INDEX


def _range(seed0: int, n: int = 10_000) -> set[int]:
    return set(range(seed0, seed0 + n))


def test_seed_ranges_are_disjoint_and_outside_every_evaluation_range():
    from spark_core.perception.learned.dataset import BENCH_SEED0, DEV_SEED0, TRAIN_SEED0
    from spark_core.perception.learned.libero_data import LIBERO_BENCH_SEED0, LIBERO_DEV_SEED0, LIBERO_TRAIN_SEED0

    ours = [_range(cb.CAPBENCH_TRAIN_SEED0), _range(cb.CAPBENCH_BENCH_SEED0, 5000), _range(cb.CAPBENCH_DEV_SEED0, 5000)]
    others = [set(range(1000))] + [  # task benchmarks: seeds 0..999; the other sources' ranges as they are used
        _range(s, n)
        for s, n in (
            (TRAIN_SEED0, 10_000),
            (BENCH_SEED0, 6_000),
            (DEV_SEED0, 6_000),
            (LIBERO_TRAIN_SEED0, 10_000),
            (LIBERO_BENCH_SEED0, 6_000),
            (LIBERO_DEV_SEED0, 6_000),
        )
    ]
    for i, a in enumerate(ours):
        assert all(not a & b for b in ours[i + 1 :] + others)


def test_seeds_take_the_seven_tasks_in_turn():
    for seed0 in (cb.CAPBENCH_TRAIN_SEED0, cb.CAPBENCH_BENCH_SEED0, cb.CAPBENCH_DEV_SEED0):
        assert cb.task_of_seed(seed0) == "Lift"  # each range starts a cycle
        tasks = [cb.task_of_seed(seed0 + k) for k in range(7 * cb.SCENES_PER_TASK)]
        assert sorted(set(tasks)) == sorted(cb.TASKS) and len(cb.TASKS) == 7
        assert all(tasks.count(t) == cb.SCENES_PER_TASK for t in cb.TASKS)


def test_capbench_objects_map_to_honest_categories():
    assert {cb.OBJECT_BODIES[b] for b in ("cube_main", "cubeA_main")} == {("block", "red")}
    assert cb.OBJECT_BODIES["cubeB_main"] == ("block", "green")
    assert CATEGORIES[cb.category_index("nut")].name == "nut"
    assert CATEGORIES[cb.category_index("peg")].name == "peg"
    for body, name in (("pot_root", "pot"), ("hammer_root", "hammer")):  # their own kinds, not "background"
        assert CATEGORIES[cb.category_index(cb.OBJECT_BODIES[body][0])].name == name
    assert CATEGORIES[cb.category_index("dirt")].name == "dirt"


def _stack_seed(k: int) -> int:
    seed = cb.CAPBENCH_DEV_SEED0 + cb.SCENES_PER_TASK * cb.TASKS.index("Stack") + k
    assert cb.task_of_seed(seed) == "Stack"
    return seed


def test_a_stack_scene_renders_a_red_and_a_green_block(monkeypatch):
    """Labels of a rendered Stack scene: two block instances, one red and one green, nothing else but table,
    robot and background; built by make_env from a seed outside the benchmark's 0..999."""
    pytest.importorskip("robosuite")
    from spark_core.perception.learned.dataset import render_labelled
    from spark_core.sim import capbench_envs

    built = []
    real = capbench_envs.make_env
    monkeypatch.setattr(capbench_envs, "make_env", lambda name, seed: built.append(seed) or real(name, seed))
    scenes = cb.CapbenchScenes()
    try:
        world = scenes.scene(_stack_seed(1))
        f = render_labelled(world, "agentview", cb.capbench_geom_tables(world))
    finally:
        scenes.close()
    assert built and min(built) >= 1000
    seen = {CATEGORIES[c].name for c in np.unique(f.category)}
    assert seen == {"background", "table", "robot", "block"}, seen
    colours = set()
    for i in np.unique(f.instance[f.instance > 0]):
        assert set(np.unique(f.category[f.instance == i])) == {CATEGORY_INDEX["block"]}
        colours.add(int(np.bincount(f.colour[f.instance == i]).argmax()))
    assert colours == {COLOUR_INDEX["red"], COLOUR_INDEX["green"]}


def test_nut_assembly_labels_the_nut_and_both_pegs():
    """Per-geom labels of a NutAssemblySquare world: the square nut (ring and handle) is one nut instance, each
    peg a peg instance, numbered as the scene's objects; the table TABLE, the arm ROBOT (no render: the tables
    alone)."""
    pytest.importorskip("robosuite")
    from spark_core.sim.cameras import label_table

    scenes = cb.CapbenchScenes(perturb=False)
    try:
        seed = cb.CAPBENCH_DEV_SEED0 + cb.SCENES_PER_TASK * cb.TASKS.index("NutAssemblySquare")
        world = scenes.scene(seed)
        cat, inst, _ = cb.capbench_geom_tables(world)
        m = world.model

        def of(body: str) -> tuple[set[str], set[int]]:
            geoms = [g for g in range(m.ngeom) if m.body(int(m.geom_bodyid[g])).name == body]
            return {CATEGORIES[cat[g]].name for g in geoms}, {int(inst[g]) for g in geoms}

        nut, pegs = of("SquareNut_main"), [of("peg1"), of("peg2")]
        arm_bodies = [m.body(b).id for n in world.scene.robots.values() for b in n.bodies]
        robot = {CATEGORIES[c].name for c in cat[np.isin(m.geom_bodyid, arm_bodies)]}
        table = {CATEGORIES[c].name for c in cat[m.geom_bodyid == m.body("table").id]}
        object_id = {label: i for i, label in label_table(world)[0].items()}
    finally:
        scenes.close()
    assert nut[0] == {"nut"} and len(nut[1]) == 1 and 0 not in nut[1]
    assert [p[0] for p in pegs] == [{"peg"}, {"peg"}]
    assert len({*pegs[0][1], *pegs[1][1], *nut[1]}) == 3  # three instances
    # numbered as the scene's objects (the perception bench finds each label's true mask by it)
    assert nut[1] == {object_id["square nut"]} and pegs[0][1] == {object_id["square peg"]}
    assert robot == {"robot"} and table == {"table"}


def test_the_same_seed_gives_the_same_scene():
    """A seed's scene does not depend on what the env rendered before: the env is built from the block's first
    seed and reset from the scene's own; another seed moves the cubes."""
    pytest.importorskip("robosuite")
    a, b = cb.CapbenchScenes(), cb.CapbenchScenes()
    try:

        def state(scenes, seed):
            w = scenes.scene(seed)
            return np.concatenate([w.data.qpos.copy(), w.model.light_diffuse.ravel().copy()])

        first = state(a, _stack_seed(2))
        later = state(a, _stack_seed(3))
        again = state(b, _stack_seed(3))  # a fresh env, straight to the second seed
    finally:
        a.close()
        b.close()
    np.testing.assert_allclose(later, again, atol=1e-9)
    assert np.abs(first - later).max() > 1e-3


def test_the_dataset_command_writes_a_capbench_shard(tmp_path, capsys):
    pytest.importorskip("robosuite")
    out = tmp_path / "capb"
    seed = _stack_seed(3)  # and the next seed: two Stack scenes
    args = ["perception", "dataset", "--source", "capbench", "--out", str(out), "--scenes", "2", "--seed", str(seed)]
    assert main([*args, "--cameras", "agentview"]) == 0
    assert '"source": "capbench"' in capsys.readouterr().out
    d = dict(np.load(out / f"shard_{seed}.npz"))
    assert set(d) == {"rgb", "depth_mm", "category", "instance", "colour", "seeds"}
    assert d["rgb"].shape[1:] == (240, 320, 3) and len(d["rgb"]) == 4  # 2 scenes x 1 view x 2 crops
    assert sorted(set(d["seeds"].tolist())) == [seed, seed + 1]
    assert CATEGORY_INDEX["block"] in set(np.unique(d["category"]).tolist())


def test_capbench_bench_scenes_are_held_out():
    """The perception bench's capbench scenes: every task, each seed a scene of the task it is listed under,
    outside the training range and 0..999; a later round is new; more scenes per task than a round holds are
    refused (nothing is built here)."""
    from spark_core.bench.perception_bench import _scene_worlds

    first = _scene_worlds("capbench", 3)
    assert sorted({name for name, _, _ in first}) == sorted(cb.TASKS) and len(first) == 21
    later = _scene_worlds("capbench", 3, round_=1)
    for name, seed, _ in first + later:
        assert cb.task_of_seed(seed) == name
        assert 1000 <= seed < cb.CAPBENCH_TRAIN_SEED0 and seed >= cb.CAPBENCH_BENCH_SEED0
    assert not {s for _, s, _ in first} & {s for _, s, _ in later}
    with pytest.raises(ValueError, match="overrun"):
        _scene_worlds("capbench", cb.SCENES_PER_TASK + 1)
