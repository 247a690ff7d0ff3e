"""Training-scene rearrangement (learned/rearrange.py): objects trade places and a bowl ends up standing on a raised
support (the stove, the cabinet), from the scene seed alone and never from an evaluation init state."""

import numpy as np
import pytest

from tests.perception.test_learned_libero import no_init_states  # noqa: F401  (fixture)

SEED0 = 912_000  # development scenes (libero_data.LIBERO_DEV_SEED0): task 0, a spatial-swap scene with two bowls


def _xy(world) -> dict[str, np.ndarray]:
    from spark_core.perception.learned.rearrange import movables

    return {mv.label: world.data.qpos[mv.qadr : mv.qadr + 3].copy() for mv in movables(world)}


@pytest.mark.usefixtures("no_init_states")
def test_swaps_trade_places_and_stacks_stand_on_their_support():
    from spark_core.perception.learned.libero_data import LiberoScenes, libero_tasks
    from spark_core.perception.learned.rearrange import _subtree, world_box

    task = libero_tasks()[0]
    plain, moved = LiberoScenes(perturb=False), LiberoScenes(perturb=False, rearrange=True)
    swaps = stacks = 0
    try:
        for seed in range(SEED0, SEED0 + 8):
            before = _xy(plain.scene(seed, task))
            world = moved.scene(seed, task)
            after, table_z = _xy(world), float(world.origin_m[2])
            assert set(before) == set(after)
            kinds = [k for k, _, _ in moved.moves]
            for kind, a, b in moved.moves:
                if kind == "swap":
                    # each settled where the other stood (unless a stack then moved one of them on)
                    if not any(k == "stack" and x in (a, b) for k, x, _ in moved.moves):
                        assert np.linalg.norm(after[a][:2] - before[b][:2]) < 0.04, (a, b)
                        assert np.linalg.norm(after[b][:2] - before[a][:2]) < 0.04, (a, b)
                        swaps += 1
                elif kind == "stack" and "gave up" not in kinds and b in ("flat stove", "wooden cabinet"):
                    m, d = world.model, world.data  # fixtures: nothing knocks them over
                    lo, hi = world_box(m, d, _subtree(m, m.body(world.scene.objects[b].body).id))
                    assert lo[0] - 0.02 < after[a][0] < hi[0] + 0.02 and lo[1] - 0.02 < after[a][1] < hi[1] + 0.02
                    assert after[a][2] > table_z + 0.02, (a, b, after[a][2] - table_z)
                    stacks += 1
            moves = list(moved.moves)
            again = moved.scene(seed, task)  # same seed, same moves, same places
            assert moved.moves == moves and np.allclose(
                np.array(list(_xy(again).values())), np.array(list(after.values())), atol=1e-6
            )
    finally:
        plain.close()
        moved.close()
    assert swaps >= 1 and stacks >= 1, (swaps, stacks)


def test_rearrange_is_for_libero_scenes_only(tmp_path):
    from spark_core.perception.learned.dataset import generate

    with pytest.raises(ValueError, match="libero source only"):
        generate(tmp_path, 1, 1, source="builtin", rearrange=True)
