"""Build the resolver a trial's segmenter needs (the catalog's names; see spark_core.catalog.SEGMENTERS)."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from .noisy_segmenter import NoiseModel, SimNoisySegmenter
from .privileged import PrivilegedResolver
from .resolver import PerceptionResolver
from .sim_segmenter import SimSegmenter

DEFAULT_CAMERAS = ("agentview", "side")


def make_segmenter(
    name: str, world: Any, seed: int = 0, noise: NoiseModel = NoiseModel(), sam3_model: str | None = None
):
    """The named camera segmenter. `sim` and `sim-noisy` are oracles (the scene's object catalog); `learned`
    reads RGB-D only (weights shipped in the package); `sam3` reads RGB only (its checkpoint from `sam3_model`
    or SPARK_SAM3_MODEL; a clear error when it is absent)."""
    if name == "sim":
        return SimSegmenter(world.scene.catalog())
    if name == "sim-noisy":
        return SimNoisySegmenter(SimSegmenter(world.scene.catalog()), noise, seed)
    if name == "learned":
        from .learned.segmenter import LearnedSegmenter

        return LearnedSegmenter()
    if name == "sam3":
        from .sam3_segmenter import Sam3Segmenter

        return Sam3Segmenter(sam3_model)
    raise ValueError(f"no camera segmenter {name!r}")


def make_resolver(
    world: Any,
    segmenter: str,
    seed: int = 0,
    cameras: Sequence[str] | None = None,
    adaptive: bool = True,
    noise: NoiseModel = NoiseModel(),
    sam3_model: str | None = None,
):
    """label -> keypoint for one trial: the privileged-keypoints source, or cameras + the named segmenter.
    `cameras` None means the scene's own perception cameras."""
    if segmenter == "privileged-keypoints":
        return PrivilegedResolver(world)
    cams = tuple(cameras or world.scene.extra.get("perception_cameras", DEFAULT_CAMERAS))
    missing = [c for c in cams if c not in world.scene.cameras]
    if missing:
        raise ValueError(f"camera(s) {', '.join(missing)} not in this scene; it has {', '.join(world.scene.cameras)}")
    return PerceptionResolver(
        world, make_segmenter(segmenter, world, seed, noise, sam3_model), cameras=cams, adaptive=adaptive
    )
