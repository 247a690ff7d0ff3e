"""Mid-task training scenes (learned/mid_task.py): a drawer pulled out, the hand posed just above an object or at the
open drawer, sometimes holding the object, from the scene seed alone and never from an evaluation init state."""

import numpy as np
import pytest

from tests.perception.test_learned_libero import no_init_states  # noqa: F401  (fixture)

SEED0 = 912_000  # development scenes (libero_data.LIBERO_DEV_SEED0)


def _state(world) -> np.ndarray:
    return np.concatenate([world.data.qpos.copy(), [world.data.site_xpos[world._tcp[world.arms[0]]][2]]])


@pytest.mark.usefixtures("no_init_states")
def test_drawers_open_and_the_hand_reaches_and_holds_from_the_seed():
    from spark_core.perception.learned.libero_data import LiberoScenes, libero_tasks
    from spark_core.perception.learned.mid_task import drawer_joints
    from spark_core.perception.learned.rearrange import _subtree, movables, world_box

    task = next(t for t in libero_tasks() if t.name.endswith("open_the_top_drawer_and_put_the_bowl_inside"))
    scenes = LiberoScenes(perturb=False, mid_task=True)
    seen: set[str] = set()
    try:
        for seed in range(SEED0, SEED0 + 80):  # until all three were seen (about 1 scene in 10 holds something)
            if seen == {"opened", "reached", "held"}:
                break
            world = scenes.scene(seed, task)
            m, d = world.model, world.data
            travel = [abs(float(d.qpos[m.jnt_qposadr[j]])) / np.abs(m.jnt_range[j]).max() for j in drawer_joints(world)]
            assert travel, "the goal scene's cabinet has drawers"
            if "drawer opened" in scenes.mid:
                assert max(travel) > 0.3, travel  # pulled out (and still out after the settle)
                seen.add("opened")
            else:
                assert max(travel) < 0.1, travel  # LIBERO's reset: all closed
            grip = d.site_xpos[world._tcp[world.arms[0]]]
            for done in scenes.mid:
                label = done.removeprefix("hand at ").removeprefix("holding ")
                if not done.startswith("hand at") or label == "open drawer":
                    continue
                body = m.body(world.scene.objects[label].body).id
                lo, hi = world_box(m, d, _subtree(m, body))
                if "holding" in done:  # the object hangs between the fingers
                    assert np.linalg.norm((lo + hi) / 2 - grip) < 0.01
                    assert label in {mv.label for mv in movables(world)}
                    seen.add("held")
                else:  # the grip point just above the object's top, within the jitter of its middle
                    assert hi[2] < grip[2] < hi[2] + 0.17, (label, grip[2] - hi[2])
                    assert np.all(np.abs(grip[:2] - (lo[:2] + hi[:2]) / 2) < (hi[:2] - lo[:2]) / 2 + 0.1)
                    seen.add("reached")
            first = (list(scenes.mid), _state(world))
            again = scenes.scene(seed, task)  # same seed, same scene
            assert scenes.mid == first[0] and np.allclose(_state(again), first[1], atol=1e-6)
    finally:
        scenes.close()
    assert seen == {"opened", "reached", "held"}, seen


def test_mid_task_is_for_libero_scenes_only(tmp_path):
    from spark_core.perception.learned.dataset import generate

    with pytest.raises(ValueError, match="--mid-task applies to the libero source only"):
        generate(tmp_path, 1, 1, source="builtin", mid_task=True)
