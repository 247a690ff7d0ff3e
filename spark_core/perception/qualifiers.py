"""Spatial qualifiers in object phrases ("the left mug", "the bowl nearest the robot")."""

from __future__ import annotations

import re

# qualifier -> (world axis index, sign): the chosen instance maximises sign * coordinate.
# World frame: x forward (away from the robot), y left (robot's view).
QUALIFIERS: dict[str, tuple[int, float]] = {
    "left": (1, 1.0), "leftmost": (1, 1.0), "right": (1, -1.0), "rightmost": (1, -1.0),
    "front": (0, -1.0), "nearest": (0, -1.0), "closest": (0, -1.0), "near": (0, -1.0),
    "back": (0, 1.0), "far": (0, 1.0), "farthest": (0, 1.0), "furthest": (0, 1.0), "rear": (0, 1.0),
}
_ARTICLES = re.compile(r"\b(the|a|an|one|of|to|robot|from)\b", re.I)


def split_qualifier(prompt: str) -> tuple[str | None, str]:
    """('left', 'mug') for 'the left mug'; (None, prompt) when there is no spatial qualifier."""
    words = prompt.lower().replace("-", " ").split()
    for i, w in enumerate(words):
        if w in QUALIFIERS:
            rest = " ".join(words[:i] + words[i + 1:])
            core = _ARTICLES.sub(" ", rest).split()
            return w, " ".join(core) if core else rest
    return None, prompt
