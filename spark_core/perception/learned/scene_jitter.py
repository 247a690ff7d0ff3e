"""What the robosuite-based training-data sources (LIBERO, CaP-Bench) do to every scene alike: reset with numpy's
global RNG seeded from the scene seed, and jitter lighting and the arms' joints from the same seed."""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager

import numpy as np

ARM_JITTER_P = 0.7  # share of scenes whose arms are moved off the reset pose
ARM_JITTER_RAD = 0.3  # standard deviation of each joint's offset


@contextmanager
def seeded_numpy(seed: int) -> Iterator[None]:
    """robosuite's and LIBERO's samplers draw from numpy's global RNG: seed it for the reset, then put the caller's
    state back."""
    state = np.random.get_state()
    np.random.seed(seed % 2**32)
    try:
        yield
    finally:
        np.random.set_state(state)


def jitter(world, light0: tuple[np.ndarray, np.ndarray], seed: int, perturb: bool) -> None:
    """Put the lights back to `light0` (diffuse, position), then, with `perturb`, scale their colour by 0.7-1.3,
    move them in xy and, in ARM_JITTER_P of scenes, offset the arms' joints; all from `seed`. qpos only: the caller
    runs mj_forward."""
    m, d = world.model, world.data
    m.light_diffuse[:], m.light_pos[:] = light0
    if not perturb:
        return
    rng = np.random.default_rng(seed)
    m.light_diffuse[:] = m.light_diffuse * rng.uniform(0.7, 1.3)
    m.light_pos[:, :2] += rng.normal(0, 0.25, (m.nlight, 2))
    if rng.random() < ARM_JITTER_P:
        for arm in world.arms:
            adr = world._qadr[arm]
            d.qpos[adr] = d.qpos[adr] + rng.normal(0, ARM_JITTER_RAD, len(adr))
