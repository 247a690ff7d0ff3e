"""Perception: segmenters, 3D keypoints, adaptive prompts, label resolution, scene summaries."""

from .detection import Detection
from .frame import CameraFrame
from .keypoint import Keypoint, LabelNotFound
from .learned.segmenter import LearnedSegmenter
from .noisy_segmenter import NoiseModel, SimNoisySegmenter
from .resolver import PerceptionResolver
from .segmenter import Segmenter
from .sim_segmenter import SimSegmenter

__all__ = [
    "CameraFrame",
    "Detection",
    "Keypoint",
    "LabelNotFound",
    "LearnedSegmenter",
    "NoiseModel",
    "PerceptionResolver",
    "Segmenter",
    "SimNoisySegmenter",
    "SimSegmenter",
]
