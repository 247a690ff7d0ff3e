"""Primitive implementations on a World; `PrimitiveLibrary` is the Actuator the executor uses."""

from .base import IMPLEMENTATIONS
from .primitive_library import PrimitiveLibrary

__all__ = ["IMPLEMENTATIONS", "PrimitiveLibrary"]
