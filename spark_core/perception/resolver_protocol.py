"""The Resolver protocol: label -> keypoint at call time. Execution and planning both read perception through it."""

from __future__ import annotations

from typing import Protocol, runtime_checkable

from .keypoint import Keypoint


@runtime_checkable
class Resolver(Protocol):
    """label -> Keypoint from the latest perception, at the moment a node runs."""

    def resolve(self, label: str) -> Keypoint:
        """Raises perception.LabelNotFound when the label has no single confident detection."""
        ...

    def refresh(self) -> None:
        """Re-detect (new images, new masks) so the next resolve sees the current scene."""
        ...
