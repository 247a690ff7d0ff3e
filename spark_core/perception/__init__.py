"""Perception: segmenters, 3D keypoints, label resolution."""

from .keypoint import Keypoint, LabelNotFound

__all__ = ["Keypoint", "LabelNotFound"]
