"""`sim` segmenter (the offline default): PRIVILEGED masks from the renderer's object ids, with text prompts
grounded to scene objects by sentence similarity over each object's label and description."""

from __future__ import annotations

import re
from collections.abc import Mapping, Sequence

import numpy as np

from .colors import colours_in, normalise_colours
from .detection import Detection
from .frame import CameraFrame
from .learned.categories import libero_description
from .naming import ANYTHING, class_members, mismatch, own_noun_prompts, package_members
from .qualifiers import (
    QUALIFIERS,
    SIZE_AXIS,
    anchor_apart,
    on_side,
    ruled_out_parts,
    split_qualifier,
    split_relation,
)
from .text_encoder import SHARED_ENCODER, TextEncoder
from .variants import (
    SPELLINGS,
)

HEAD_NOUN_BONUS = 0.08
# An object whose colour, shape or kind contradicts the prompt is no match at any similarity: the score drops by
# this much (below any threshold; kept as a score so noise models can still rank confusions).
MISMATCH_PENALTY = 1.0


def calibrated_score(cosine: float, threshold: float) -> float:
    """Map a cosine similarity to [0, 1] with 0.5 at the threshold (logistic, 0.05 cosine per e-fold)."""
    return float(1.0 / (1.0 + np.exp(-(cosine - threshold) / 0.05)))


class SimSegmenter:
    """Grounding: a score per scene object from cosine(prompt, "label: description"). Objects scoring above
    `threshold` and within `margin` of the best all become detections where they are in view (two black bowls
    give two); a spatial qualifier ("left", "nearest") then keeps the one instance it points at.

    Everything it returns is marked privileged (masks from simulator ground truth).
    """

    name = "sim"
    privileged = True

    def __init__(
        self,
        catalog: Mapping[str, str],
        threshold: float = 0.33,
        margin: float = 0.07,
        encoder: TextEncoder | None = None,
    ):
        self.catalog = dict(catalog)  # object label -> description
        self.threshold = threshold
        self.margin = margin
        self.encoder = encoder or SHARED_ENCODER
        # an instance number ("bowl 2") is no visual property: two bowls must ground alike, for a qualifier or a
        # relation to choose between them
        self._names = _instance_names(self.catalog)
        self._docs = [f"{self._names[label]}: {desc}" for label, desc in self.catalog.items()]
        self._doc_vecs = self.encoder.encode(self._docs) if self._docs else np.zeros((0, 384))
        self._labels = list(self.catalog)
        # what each thing comes in, for a prompt that names only a package ("the carton"): its description, and for
        # a LIBERO object (described by its name alone) the package its category's description says
        self._package_docs = [
            f"{desc} {libero_description(self._names[label])}" for label, desc in self.catalog.items()
        ]
        self._similar: dict[str, dict[str, float]] = {}  # prompt text -> `similarities`

    def similarities(self, text: str) -> dict[str, float]:
        """`_similarities`, worked out once per text: every frame and view asks again, and the naming rules run
        against every object."""
        if text not in self._similar:
            self._similar[text] = self._similarities(text)
        return dict(self._similar[text])

    def _similarities(self, text: str) -> dict[str, float]:
        """Grounding score per object: cosine of the colour-normalised prompt with "label: description", plus
        a bonus when the prompt's head noun is the object's own noun (so "the stove" prefers the stove over
        its knob), minus MISMATCH_PENALTY when the prompt contradicts the object (`mismatch`)."""
        if not self._labels:
            return {}
        norm = " ".join(SPELLINGS.get(w, w) for w in normalise_colours(text).split())
        q = self.encoder.encode([norm])[0]
        cos = self._doc_vecs @ q
        # a word the kinds table files with the object's own noun is that noun ("platter" for a plate, "hob" for a
        # stove): the object scores at least as the prompt with its own noun in that word's place would
        own = own_noun_prompts(norm, [self._names[label] for label in self._labels])
        if own:
            own_vecs = self.encoder.encode(list(own.values()))
            for (i, _), v in zip(own.items(), own_vecs):
                cos[i] = max(cos[i], float(self._doc_vecs[i] @ v))
        words = norm.split()
        head = words[-1] if words else ""
        # a part's noun names the part when some object is one ("the handle of the drawer"); only when none is
        # may it name the whole it belongs to ("the stove knob" of a stove without a separate knob)
        strict = {
            label: mismatch(text, self._names[label], self.catalog[label], part_is_whole=False)
            for label in self._labels
        }
        whole = all(strict.values())
        # a word for a class ("the container", "the dairy product") names each thing WordNet files under it alike
        # and nothing else, however the encoder ranks them (naming.class_members)
        members = class_members(norm, [self._names[label] for label in self._labels])
        if members is None:  # "the carton": each thing that comes in one (naming.package_members)
            members = package_members(norm, self._package_docs)
        # "the bottle": a thing of that kind, or one that comes in a bottle (the ketchup's)
        # (on the words as said: "mustard" is a colour to normalise_colours, and a food that says which bottle)
        packed = set() if members is not None else package_members(text, self._package_docs, kind_too=True) or set()
        if packed:
            members = packed | {k for k, label in enumerate(self._labels) if strict[label] is None}
        if members is None and norm.strip() in ANYTHING:
            # "the item closest to you" (its qualifier split off before): a word that names anything names each
            # thing alike, for the qualifier to choose
            members = set(range(len(self._labels)))
        out = {}
        for k, (label, c) in enumerate(zip(self._labels, cos.tolist())):
            if head and head == self._names[label].split()[-1]:
                c += HEAD_NOUN_BONUS
            mismatched = mismatch(text, self._names[label], self.catalog[label]) if whole else strict[label]
            if members is not None and (not mismatched or k in packed):
                c = max(self.threshold, max(float(cos[m]) for m in members)) if k in members else c - MISMATCH_PENALTY
            elif mismatched:
                c -= MISMATCH_PENALTY
            out[label] = c
        return self._colour_said(text, out)

    def _colour_said(self, text: str, scores: dict[str, float]) -> dict[str, float]:
        """ "the black dish" with a black bowl and a plate whose name says no colour: a colour the prompt names
        picks the object whose name says it over one whose name says none, when both would match otherwise."""
        want = colours_in(text)
        said = {label: colours_in(f"{self._names[label]} {self.catalog[label]}") for label in self._labels}
        if not want or not any(said[label] & want and scores[label] >= self.threshold for label in self._labels):
            return scores
        return {label: c - (MISMATCH_PENALTY if not said[label] else 0.0) for label, c in scores.items()}

    def names_in(self, frame: CameraFrame) -> list[str]:
        """The names of the catalogued objects this frame shows, once per instance (two black bowls: the name twice;
        privileged: from the renderer's object ids)."""
        if frame.object_ids is None:
            return []
        shown = (frame.labels.get(int(i)) for i in np.unique(frame.object_ids) if i)
        return sorted(self._names[label] for label in shown if label in self._names)

    def segment(self, frame: CameraFrame, prompts: Sequence[str]) -> list[Detection]:
        if frame.object_ids is None:
            raise ValueError(
                "the sim segmenter needs per-pixel object ids: this frame has none (not from the simulator)"
            )
        visible = {frame.labels[i]: i for i in np.unique(frame.object_ids) if i and i in frame.labels}
        out: list[Detection] = []
        for prompt in prompts:
            head, relation, anchors = split_relation(prompt)
            if relation is not None:
                out.extend(self._related(frame, prompt, head, anchors, relation))
                continue
            unlike = re.fullmatch(r"(.+?) not (.+)", prompt.strip().lower())
            if unlike and _is_qualifier(unlike.group(2)):
                # "bowl not leftmost": every instance but the one the qualifier picks
                core, said = unlike.group(1), unlike.group(2)
                ruled_out = {d.detail["object"] for d in self.segment(frame, [f"{said} {core}"])}
                out.extend(
                    Detection(prompt, prompt, d.mask, d.score, d.camera, d.privileged, {**d.detail, "unlike": said})
                    for d in self.segment(frame, [core])
                    if d.detail["object"] not in ruled_out
                )
                continue
            if unlike:  # "block not blue", "box not cream cheese nor chocolate pudding"
                core, said = unlike.group(1), unlike.group(2)
                named = [(part, self._named_by(frame, part, core)) for part in ruled_out_parts(said)]
                out.extend(
                    Detection(prompt, prompt, d.mask, d.score, d.camera, d.privileged, {**d.detail, "unlike": said})
                    for d in self.segment(frame, [core])
                    if all(self._rules_out(part, core, d.detail["object"], by) for part, by in named)
                )
                continue
            rank, prompt_q = split_rank(prompt)
            qualifier, core = split_qualifier(prompt_q)
            sims = self.similarities(core)
            if not sims:
                continue
            # The match is decided over every object in the scene, then cut to what this view shows: a hidden
            # drawer does not turn a "drawer" prompt into a detection of the cabinet that hides it.
            best = max(sims.values())
            chosen = [k for k, v in sims.items() if v >= self.threshold and v >= best - self.margin and k in visible]
            dets = [
                Detection(
                    prompt,
                    prompt,
                    frame.object_ids == visible[k],
                    calibrated_score(sims[k], self.threshold),
                    frame.camera,
                    True,
                    {"object": k, "cosine": round(sims[k], 4)},
                )
                for k in chosen
            ]
            if qualifier and rank > 1:  # "second leftmost bowl": counted from the left; too few seen, none
                dets = [pick_by_qualifier(dets, frame, qualifier, rank)] if len(dets) >= rank else []
            elif qualifier and len(dets) > 1:
                dets = [pick_by_qualifier(dets, frame, qualifier)]
            out.extend(dets)
        return out

    def _named_by(self, frame: CameraFrame, said: str, core: str) -> set[str]:
        """What "<core> not <said>" rules out: what the said words ground to alone, else with the core ("box not
        chocolate pudding": the chocolate pudding; "milk carton not oj": the orange juice, where "oj milk carton" is
        the milk; "peg not round": the round peg); empty when neither grounds to anything."""
        for prompt in (said, f"{said} {core}"):
            named = {d.detail["object"] for d in self.segment(frame, [prompt])}
            if named:
                return named
        return set()

    def _rules_out(self, said: str, core: str, label: str, named: set[str]) -> bool:
        """Whether the object is left out: not among what the said words name (`_named_by`), or, when they name
        nothing, contradicted by them ("block not blue": the blue block)."""
        if named:
            return label not in named
        return mismatch(f"{said} {core}", self._names[label], self.catalog[label]) is not None

    def _supported(
        self, frame: CameraFrame, dets: list[Detection], relation: str, anchors: list[str]
    ) -> list[bool] | None:
        """For "on" and "in" one anchor: whether each instance rests on it (its centre over the anchor's footprint
        and above its top) or is inside it (over its footprint, below its top): a bowl in a cabinet's drawer and a
        bowl on the cabinet are both nearest the cabinet in the table plane. None when the relation is another,
        the anchor is not seen, or this tells no single instance apart (then nearness decides)."""
        rel = relation.removeprefix("not ")
        if rel not in ("on", "on top of", "in", "inside") or len(anchors) != 1:
            return None
        ids = {d.detail.get("object") for d in dets}
        cands = [d for d in self.segment(frame, [anchors[0]]) if d.detail.get("object") not in ids]
        if not cands:
            return None
        anchor = _points(max(cands, key=lambda d: d.score), frame)
        if len(anchor) < 10:
            return None
        lo, hi = np.percentile(anchor[:, :2], 2, axis=0), np.percentile(anchor[:, :2], 98, axis=0)
        top = float(np.percentile(anchor[:, 2], 98))
        on, inside = [], []
        for d in dets:
            centre = np.median(_points(d, frame), axis=0)
            over = bool(np.all(centre[:2] >= lo - SUPPORT_SLACK_M) and np.all(centre[:2] <= hi + SUPPORT_SLACK_M))
            above = float(centre[2]) >= top - SUPPORT_SLACK_M
            on.append(over and above)
            inside.append(over and not above)
        if rel.startswith("on"):
            return on if sum(on) == 1 else None
        if sum(inside) == 1:
            return inside
        # what rests on top of it is not in it (a drawer's bowl may stand out of the cabinet's seen footprint)
        rest = [not o for o in on]
        return rest if any(on) and sum(rest) == 1 else None

    def _related(
        self, frame: CameraFrame, prompt: str, head: str, anchors: list[str], relation: str
    ) -> list[Detection]:
        """Instances of `head`; when several, the one resting on or inside the anchor ("on", "in": `_supported`),
        else the one nearest the anchor objects (their midpoint for "between"), or the farthest when negated ("not
        between")."""
        negated = relation.startswith("not ")
        dets = self.segment(frame, [head])
        assert frame.object_ids is not None  # segment() refuses frames without object ids
        found = []
        for a in anchors:
            cands, dets = anchor_apart(dets, self.segment(frame, [a]), "object")
            if cands:
                found.append(_centroid_xy(max(cands, key=lambda d: d.score), frame))
        if len(dets) > 1 and not found and any(w in a for a in anchors for w in ("center", "centre", "middle")):
            found = [_middle_xy(frame)]  # "from the table center"
        supported = self._supported(frame, dets, relation, anchors) if len(dets) > 1 else None
        # "the thing on the stove": of no kind, only what rests on or in it is meant, never the nearest thing
        kindless = head.split()[-1:] and head.split()[-1] in ANYTHING
        if supported is None and kindless and relation.removeprefix("not ") in ("on", "on top of", "in", "inside"):
            return []
        if supported is not None:  # "on" / "in" said by where it rests, not by how near it is
            dets = [d for d, holds in zip(dets, supported) if holds != negated]
        elif len(dets) > 1 and found:
            target = np.mean(found, axis=0)
            sided = [d for d in dets if on_side(relation, _centroid_xy(d, frame), target) != negated]
            dets = sided or dets  # "the bowl left of the plate": of those on that side, the nearest
            pick = max if negated and not sided else min
            dets = [pick(dets, key=lambda d: float(np.linalg.norm(_centroid_xy(d, frame) - target)))]
        return [
            Detection(
                prompt, prompt, d.mask, d.score, d.camera, d.privileged, {**d.detail, "relation_anchors": anchors}
            )
            for d in dets
        ]


def _instance_names(catalog: Mapping[str, str]) -> dict[str, str]:
    """label -> the name grounded against: a second copy of a kind ("bowl 2", described exactly like "bowl") drops
    its number, which is no visual property; numbered parts that are described apart ("pot handle 0") keep it."""
    base = {label: re.sub(r" [0-9]+$", "", label) for label in catalog}
    kinds: dict[tuple[str, str], int] = {}
    for label, desc in catalog.items():
        kinds[(base[label], desc)] = kinds.get((base[label], desc), 0) + 1
    return {label: base[label] if kinds[(base[label], catalog[label])] > 1 else label for label in catalog}


def _middle_xy(frame: CameraFrame) -> np.ndarray:
    """The middle of the table (m, world xy): the mean centroid of everything on it in this view (needs the
    renderer's object ids)."""
    assert frame.object_ids is not None
    ids = [i for i in np.unique(frame.object_ids) if i]
    return np.mean([mask_centroid_xy(frame.object_ids == i, frame) for i in ids], axis=0)


def _centroid_xy(d: Detection, frame: CameraFrame) -> np.ndarray:
    return mask_centroid_xy(d.mask, frame)


def mask_centroid_xy(mask: np.ndarray, frame: CameraFrame) -> np.ndarray:
    """The median world xy (m) of a mask's back-projected pixels."""
    vs, us = np.nonzero(mask)
    pts = frame.backproject(us.astype(float), vs.astype(float), frame.depth_m[vs, us])
    return np.median(pts[:, :2], axis=0)


def pick_by_qualifier(
    dets: list[Detection],
    frame: CameraFrame,
    qualifier: str,
    rank: int = 1,
    table_middle_xy_m: np.ndarray | None = None,
) -> Detection:
    """The instance a spatial qualifier points at, from each mask's back-projected centroid (a size qualifier: from
    its points' footprint); `rank` counts from
    that end ("second leftmost"). "middle": the median one along the axis the instances spread along most (stacked
    drawers: height; blocks in a row on the table: across or along it)."""
    axis, sign = QUALIFIERS[qualifier]
    if axis == SIZE_AXIS:  # footprint area (m^2) between the 5th and 95th percentile of its points
        area = {
            id(d): float(np.prod(np.ptp(np.percentile(_points(d, frame)[:, :2], [5, 95], axis=0), axis=0)))
            for d in dets
        }
        return sorted(dets, key=lambda d: -sign * area[id(d)])[min(rank, len(dets)) - 1]
    centres = {id(d): np.median(_points(d, frame), axis=0) for d in dets}
    if sign == 0.0:
        spread = np.ptp(np.array(list(centres.values())), axis=0)
        axis = int(np.argmax(spread))
        if table_middle_xy_m is None and frame.object_ids is not None:
            table_middle_xy_m = _middle_xy(frame)
        if len(dets) == 2 and axis != 2 and table_middle_xy_m is not None:
            # two on the table have no median: "the middle bowl" is the one nearer the middle of the table (of
            # everything on it in this view, as "from the table center" reads it; given by a camera-only caller)
            middle = table_middle_xy_m
            return min(dets, key=lambda d: float(np.linalg.norm(centres[id(d)][:2] - middle)))
        return sorted(dets, key=lambda d: float(centres[id(d)][axis]))[len(dets) // 2]
    ordered = sorted(dets, key=lambda d: -sign * float(centres[id(d)][axis]))
    return ordered[min(rank, len(ordered)) - 1]


# Ordinal words before a qualifier ("second leftmost bowl"): how far from that end to count.
RANKS = {"second": 2, "third": 3, "fourth": 4, "fifth": 5}
# Slack when testing that a thing rests on or in another (m): masks and their depth are a little noisy at edges.
SUPPORT_SLACK_M = 0.01


def split_rank(prompt: str) -> tuple[int, str]:
    """(2, "leftmost bowl") for "second leftmost bowl"; (1, prompt) without an ordinal."""
    first, _, rest = prompt.strip().partition(" ")
    return (RANKS[first.lower()], rest) if first.lower() in RANKS and rest else (1, prompt)


def _is_qualifier(words: str) -> bool:
    """ "leftmost", "second leftmost", "top": a qualifier alone, which picks one instance of the noun before it."""
    _, rest = split_rank(words)
    return len(rest.split()) == 1 and rest in QUALIFIERS


def _points(d: Detection, frame: CameraFrame) -> np.ndarray:
    vs, us = np.nonzero(d.mask)
    return frame.backproject(us.astype(float), vs.astype(float), frame.depth_m[vs, us])
