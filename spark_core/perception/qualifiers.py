"""Spatial qualifiers in object phrases ("the left mug", "the bowl nearest the robot")."""

from __future__ import annotations

import re

import numpy as np

from .detection import Detection

# qualifier -> (world axis index, sign): the chosen instance maximises sign * coordinate.
# World frame: x forward (away from the robot), y left (robot's view).
QUALIFIERS: dict[str, tuple[int, float]] = {
    "left": (1, 1.0),
    "leftmost": (1, 1.0),
    "right": (1, -1.0),
    "rightmost": (1, -1.0),
    "front": (0, -1.0),
    "nearest": (0, -1.0),
    "closest": (0, -1.0),
    "near": (0, -1.0),
    "back": (0, 1.0),
    "far": (0, 1.0),
    "farthest": (0, 1.0),
    "furthest": (0, 1.0),
    "rear": (0, 1.0),
    # stacked instances (a cabinet's drawers, their handles): sign 0 = the middle one
    "top": (2, 1.0),
    "upper": (2, 1.0),
    "bottom": (2, -1.0),
    "lower": (2, -1.0),
    "middle": (2, 0.0),
    # size, not place: axis 3 is the footprint's area in the table plane ("the bigger cube", "the smallest bowl")
    "largest": (3, 1.0),
    "smallest": (3, -1.0),
}
SIZE_AXIS = 3
_ARTICLES = re.compile(r"\b(the|a|an|one|of|to|robot|from)\b", re.I)


# Words said for a qualifier ("the centre bowl": the middle one).
_SAID_FOR = {"centre": "middle", "center": "middle", "central": "middle"}


def split_qualifier(prompt: str) -> tuple[str | None, str]:
    """('left', 'mug') for 'the left mug'; (None, prompt) when there is no spatial qualifier."""
    words = prompt.lower().replace("-", " ").split()
    for i, w in enumerate(words):
        if w in QUALIFIERS or w in _SAID_FOR and i < len(words) - 1:  # "the centre bowl", not "the plate's centre"
            rest = " ".join(words[:i] + words[i + 1 :])
            core = _ARTICLES.sub(" ", rest).split()
            return _SAID_FOR.get(w, w), " ".join(core) if core else rest
    return None, prompt


def ruled_out_parts(said: str) -> list[str]:
    """The things a negation rules out, one per part: "cream cheese nor chocolate pudding" -> both; "blue" -> itself."""
    parts = [p.strip() for p in re.split(r"\s*,\s*|\s+(?:nor|or|and|not)\s+", said.strip())]
    return [p for p in parts if p] or [said]


# Relations to another object ("the bowl next to the plate", "the bowl between the plate and the ramekin"):
# the chosen instance is the one whose centroid is nearest (in the table plane) to the anchor(s), among those on the
# side a sided relation names ("the bowl left of the plate").
RELATIONS = (
    *("between", "next to", "beside", "near", "by", "on top of", "on", "in", "inside", "at", "from", "under"),
    *("left of", "right of", "behind", "in front of"),
)
_RELATION = re.compile(
    r"^(.+?)\s+(" + "|".join(re.escape(r) for r in sorted(RELATIONS, key=len, reverse=True)) + r")\s+(.+)$"
)


def split_relation(prompt: str) -> tuple[str, str | None, list[str]]:
    """('black bowl', 'between', ['plate', 'ramekin']) for 'black bowl between the plate and the ramekin'
    ('not between' when negated); (prompt, None, []) when the phrase names no second object."""
    m = _RELATION.match(prompt.lower().strip())
    if not m:
        return prompt, None, []
    head, relation, rest = m.group(1), m.group(2), m.group(3)
    if head.endswith(" not"):  # "the bowl not between the plate and the ramekin": the other one
        head, relation = head[: -len(" not")], f"not {relation}"
    anchors = re.split(r"\s+and\s+", rest) if relation.endswith("between") else [rest]
    anchors = [" ".join(w for w in a.split() if w not in ("the", "a", "an")) for a in anchors]
    return head.strip(), relation, [a for a in anchors if a]


SUPPORT_RELATIONS = ("on top of", "on", "in", "inside", "at", "from")  # the head stands on or in the anchor
# ("under": the head within the anchor's footprint, as for these, below it)
NEAR_RELATIONS = ("next to", "beside", "near", "by")
SUPPORT_MARGIN_M = 0.03  # a bowl's centre may overhang its support's seen footprint by this much
NEAR_M = 0.2  # "next to": centres at most the anchor's radius plus this apart (table plane)
# "left of X", "right of X" (the robot's left and right), "behind X" (farther from the robot), "in front of X"
# (nearer it): (world axis, sign) of the side the head is on
SIDED_RELATIONS: dict[str, tuple[int, float]] = {
    "left of": (1, 1.0),
    "right of": (1, -1.0),
    "behind": (0, 1.0),
    "in front of": (0, -1.0),
}


def on_side(relation: str, head_xy_m: np.ndarray, anchor_xy_m: np.ndarray) -> bool:
    """Whether a thing (its centroid in the table plane, world m) is on the side of the anchor's centre that a
    sided relation ("left of", "right of") names; any relation that names no side holds."""
    rel = relation.removeprefix("not ")
    if rel not in SIDED_RELATIONS:
        return True
    axis, sign = SIDED_RELATIONS[rel]
    return sign * (float(head_xy_m[axis]) - float(anchor_xy_m[axis])) > 0.0


def relation_holds(relation: str, head_xy_m: np.ndarray, anchors: list[tuple[np.ndarray, float]]) -> bool:
    """Whether a chosen instance (its centroid in the table plane, world m) stands in `relation` to the anchors
    (each: centroid xy and footprint radius, m) - the check a view's pick must pass to outvote another view that
    chose differently. "on/in X": within X's footprint; "next to X": within NEAR_M of its edge; "between A and
    B": nearer their midpoint than half their distance; "left/right of X": on that side of X's centre. A "not ..."
    relation holds where the relation does not."""
    negated = relation.startswith("not ")
    rel = relation[4:] if negated else relation
    centres = [np.asarray(c, float) for c, _ in anchors]
    if rel == "between" and len(centres) >= 2:
        mid = np.mean(centres, axis=0)
        holds = float(np.linalg.norm(head_xy_m - mid)) < 0.5 * float(np.linalg.norm(centres[0] - centres[1]))
    elif rel in SIDED_RELATIONS:
        holds = on_side(rel, head_xy_m, centres[0])
    else:
        (c, r), reach = anchors[0], NEAR_M if rel in NEAR_RELATIONS else SUPPORT_MARGIN_M
        holds = float(np.linalg.norm(head_xy_m - np.asarray(c, float))) <= r + reach
    return holds != negated


def anchor_apart(
    heads: list[Detection], anchored: list[Detection], key: str
) -> tuple[list[Detection], list[Detection]]:
    """The anchor detections that are not one of the head's, and the heads left once none is related to itself.
    `key` names the detail that tells things apart ("object" for the sim oracle, "instance" for the camera's own).
    "the cube under the green cube": the anchor is one of the head's kind, so when the head matched several the
    best anchor is taken out of them; one thing found for both is left as it was (a part may be named by the thing
    it is of)."""
    taken = {d.detail.get(key) for d in heads}
    cands = [d for d in anchored if d.detail.get(key) not in taken]
    if not cands and anchored and len(heads) > 1:
        cands = [max(anchored, key=lambda d: d.score)]
        heads = [d for d in heads if d.detail.get(key) != cands[0].detail.get(key)]
    return cands, heads
