"""`learned` segmenter: camera-only perception with a network trained here on our own renders (see MODEL_CARD.md).

It reads a frame's RGB and depth only (plus intrinsics/extrinsics for spatial qualifiers): never object ids,
never the simulator's object names. The network labels every pixel with a category, a colour and an
instance-boundary probability; instances are the connected parts of each category split at predicted boundaries
and depth edges. A prompt's colour words filter instances by their predicted colour; its other words pick the
category by sentence similarity with the category names and descriptions.
"""

from __future__ import annotations

import re
import threading
from collections.abc import Sequence
from dataclasses import dataclass
from importlib import resources
from pathlib import Path
from typing import Any

import cv2
import numpy as np

from ..colors import BASE_COLOURS, normalise_colours
from ..detection import Detection
from ..frame import CameraFrame
from ..qualifiers import split_qualifier, split_relation
from ..sim_segmenter import calibrated_score, pick_by_qualifier
from ..text_encoder import SHARED_ENCODER, TextEncoder
from .categories import CATEGORIES, COLOURS

WEIGHTS = "weights/learned_segmenter.pt"  # package data, next to MODEL_CARD.md
HEAD_NOUN_BONUS = 0.08
MATERIAL_WORDS = {"wooden", "wood", "metal", "plastic", "ceramic", "wicker"}  # not colour filters
MIN_INSTANCE_SCORE = 0.3  # instances the network is less sure of are dropped (stray pixels, table edges)
FRAGMENT_AREA = 0.15
BOUNDARY_PROB = 0.8  # the boundary head is trained with positives weighted 4x: 0.8 is about even odds
DEPTH_EDGE_M = 0.015  # a depth jump between neighbouring pixels larger than this (and 2 %) splits instances
_NETS: dict[str, Any] = {}
_LOCK = threading.Lock()


@dataclass(frozen=True)
class Instance:
    """One predicted object instance in a frame."""

    category: int  # index into CATEGORIES
    mask: np.ndarray  # (H, W) bool
    score: float  # median category probability over the mask, [0, 1]
    colour: str  # predicted colour name (COLOURS)


def default_weights() -> Path:
    return Path(str(resources.files(__package__).joinpath(WEIGHTS)))


def _net(path: Path):
    from .train import load_net

    key = str(path)
    with _LOCK:
        if key not in _NETS:
            if not path.is_file():
                raise FileNotFoundError(
                    f"learned segmenter weights not found at {path}: train them with `spark perception train`"
                )
            _NETS[key] = load_net(path)
        return _NETS[key]


def _words(text: str) -> list[str]:
    return re.sub(r"[^a-z ]", " ", text.lower()).split()


class LearnedSegmenter:
    """Camera-only segmenter. `threshold`: minimum cosine of a prompt with a category; categories within
    `margin` of the best one also count; instances smaller than `min_area_px` (camera pixels) are dropped."""

    name = "learned"
    privileged = False

    def __init__(
        self,
        weights: str | Path | None = None,
        threshold: float = 0.3,
        margin: float = 0.04,
        min_area_px: int = 40,
        encoder: TextEncoder | None = None,
    ):
        self.weights = Path(weights) if weights else default_weights()
        self.threshold = threshold
        self.margin = margin
        self.min_area_px = min_area_px
        self.encoder = encoder or SHARED_ENCODER
        self._things = [i for i, c in enumerate(CATEGORIES) if c.thing]
        self._doc_vecs = self.encoder.encode(
            [f"{CATEGORIES[i].name}: {CATEGORIES[i].description}" for i in self._things]
        )
        self._cache: dict[tuple, list[Instance]] = {}

    # -- grounding ---------------------------------------------------------------------------------------------
    def ground(self, text: str) -> tuple[dict[int, float], set[str]]:
        """(category index -> cosine for the categories a prompt names, colours it asks for). Colour words are
        taken out before matching the category (categories carry no colour); a trailing instance number
        ("bowl 2") is no visual property and is ignored."""
        text = _protect_named(text)
        words = [w for w in _words(normalise_colours(text)) if w not in ("the", "a", "an")]
        colours = {w for w in words if w in BASE_COLOURS and w not in MATERIAL_WORDS}
        raw = set(_words(text))
        colours -= {normalise_colours(m) for m in MATERIAL_WORDS & raw}  # "wooden" is a material here
        core = " ".join(w for w in words if w not in BASE_COLOURS) or " ".join(words)
        core = core.replace(_NAMED_MARK, " ").strip()
        if not core:
            return {}, colours
        cos = self._doc_vecs @ self.encoder.encode([core])[0]
        head = core.split()[-1]
        scores = {}
        for i, c in zip(self._things, cos.tolist()):
            name = CATEGORIES[i].name
            if head == name.split()[-1] or head.rstrip("s") == name.split()[-1]:
                c += HEAD_NOUN_BONUS
            scores[i] = c
        best = max(scores.values())
        return {i: s for i, s in scores.items() if s >= self.threshold and s >= best - self.margin}, colours

    # -- pixels -> instances -----------------------------------------------------------------------------------
    def predict(
        self, frame: CameraFrame
    ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """At network resolution (the frame shrunk by the network's factor): category index, its probability,
        boundary probability, colour probabilities (C, h, w), depth (m) per pixel, and the category
        probabilities (n_categories, h, w)."""
        import torch

        from .model import network_input, shrink

        net = _net(self.weights)
        depth = np.nan_to_num(frame.depth_m.astype(np.float32), nan=0.0, posinf=10.0)
        rgb, depth = shrink(frame.rgb, depth, net.downsample)
        depth = np.ascontiguousarray(depth)
        # One thread: on 2 shared cores a second one cost 10x the CPU time in synchronisation (measured, loaded
        # machine) for a network this small; the process's setting is restored afterwards.
        threads = torch.get_num_threads()
        torch.set_num_threads(1)
        try:
            with torch.no_grad():
                x = network_input(torch.from_numpy(rgb[None]), torch.from_numpy(depth[None]))
                cat_logits, bnd_logit, col_logits = net.split(net(x))
                probs = torch.softmax(cat_logits[0], 0)
                prob, cat = probs.max(0)
                bnd = torch.sigmoid(bnd_logit[0])
                col = torch.softmax(col_logits[0], 0)
        finally:
            torch.set_num_threads(threads)
        return cat.numpy().astype(np.int32), prob.numpy(), bnd.numpy(), col.numpy(), depth, probs.numpy()

    def instances(self, frame: CameraFrame) -> list[Instance]:
        """Every object instance the network sees in this frame (cached per frame: one prompt set per frame
        usually arrives in several calls). Instances are found at network resolution; each mask is then scaled
        to the frame by nearest pixel (at most a camera pixel off at the edges)."""
        key = (id(frame.rgb), frame.camera, frame.sim_time_s)
        if key in self._cache:
            return self._cache[key]
        cat, prob, bnd, col, depth, probs = self.predict(frame)
        H, W = frame.shape
        factor_sq = (H / cat.shape[0]) * (W / cat.shape[1])
        split = (bnd > BOUNDARY_PROB) | _depth_edges(depth)
        cat = _merge_confused(cat, probs, split)
        out: list[Instance] = []
        for c in np.unique(cat):
            if not CATEGORIES[c].thing:
                continue
            region = cat == c
            n, comp = cv2.connectedComponents((region & ~split).astype(np.uint8), connectivity=4)
            comp = _grow_into(comp, region)
            for k in range(1, n):
                m = comp == k
                if m.sum() * factor_sq < self.min_area_px:
                    continue
                score = float(np.median(prob[m]))
                if score < MIN_INSTANCE_SCORE:
                    continue
                colour_p = col[1:, m].mean(1)
                full = cv2.resize(m.astype(np.uint8), (W, H), interpolation=cv2.INTER_NEAREST).astype(bool)
                out.append(Instance(int(c), full, score, COLOURS[1 + int(colour_p.argmax())]))
        out = _drop_fragments(out)
        if len(self._cache) > 8:
            self._cache.clear()
        self._cache[key] = out
        return out

    # -- the Segmenter protocol --------------------------------------------------------------------------------
    def segment(self, frame: CameraFrame, prompts: Sequence[str]) -> list[Detection]:
        out: list[Detection] = []
        for prompt in prompts:
            head, relation, anchors = split_relation(prompt)
            if relation is not None:
                out.extend(self._related(frame, prompt, head, anchors, negated=relation.startswith("not ")))
                continue
            qualifier, core = split_qualifier(prompt)
            if re.search(r"\bof\b", prompt):  # "the top drawer of the cabinet": the drawer is the target
                core = split_qualifier(re.split(r"\bof\b", prompt)[0])[1] or core
            dets = self._matches(frame, prompt, core)
            if qualifier and len(dets) > 1:
                dets = [pick_by_qualifier(dets, frame, qualifier)]
            out.extend(dets)
        return out

    def _matches(self, frame: CameraFrame, prompt: str, core: str) -> list[Detection]:
        cats, colours = self.ground(core)
        if not cats:
            return []
        dets = []
        for k, inst in enumerate(self.instances(frame)):
            if inst.category not in cats or (colours and inst.colour not in colours):
                continue
            # grounding and pixel confidence together; their geometric mean keeps 0.5 as "as sure as not"
            score = float(np.sqrt(calibrated_score(cats[inst.category], self.threshold) * inst.score))
            detail = {"category": CATEGORIES[inst.category].name, "colour": inst.colour, "instance": k}
            dets.append(Detection(prompt, prompt, inst.mask, round(score, 4), frame.camera, False, detail))
        return dets

    def _related(
        self, frame: CameraFrame, prompt: str, head: str, anchors: list[str], negated: bool = False
    ) -> list[Detection]:
        """Instances of `head`; when several, the one nearest the anchor objects (their midpoint for "between"),
        or the farthest when negated; "the table center" is the middle of every instance in view."""
        dets = self.segment(frame, [head])
        taken = {d.detail["instance"] for d in dets}
        found = []
        for a in anchors:
            cands = [d for d in self.segment(frame, [a]) if d.detail.get("instance") not in taken]
            if cands:
                found.append(_centroid_xy(max(cands, key=lambda d: d.score).mask, frame))
        if len(dets) > 1 and not found and any(w in a for a in anchors for w in ("center", "centre", "middle")):
            found = [np.mean([_centroid_xy(i.mask, frame) for i in self.instances(frame)], axis=0)]
        if len(dets) > 1 and found:
            target = np.mean(found, axis=0)
            pick = max if negated else min
            dets = [pick(dets, key=lambda d: float(np.linalg.norm(_centroid_xy(d.mask, frame) - target)))]
        return [
            Detection(prompt, prompt, d.mask, d.score, d.camera, False, {**d.detail, "relation_anchors": anchors})
            for d in dets
        ]


_NAMED_MARK = "qq"  # glues a category name's colour word to the next word, so it is no colour filter


def _named_with_colour() -> list[str]:
    return [
        c.name for c in CATEGORIES if c.thing and any(normalise_colours(w) in BASE_COLOURS for w in c.name.split()[:-1])
    ]


def _protect_named(text: str) -> str:
    """A category whose name starts with a colour word ("orange juice", "cream cheese") is named, not coloured:
    its words are glued so colour parsing passes them over (ground() unglues them for the sentence encoder)."""
    low = " " + " ".join(_words(text)) + " "
    for name in _named_with_colour():
        if f" {name} " in low:
            low = low.replace(f" {name} ", " " + name.replace(" ", _NAMED_MARK) + " ")
    return low.strip()


CONFUSED_P = 0.15  # mean probability each of two categories gets on the other's pixels: one object, unsure which


def _merge_confused(cat: np.ndarray, probs: np.ndarray, split: np.ndarray) -> np.ndarray:
    """Within one object blob (connected object pixels, cut at boundaries and depth edges), two categories the
    network hesitates between on each other's pixels (e.g. ketchup / tomato sauce bottles) are one object of the
    category with more pixels; categories it tells apart (a block on a plate) stay separate instances."""
    thing = np.array([c.thing for c in CATEGORIES])[cat]
    n, comp = cv2.connectedComponents((thing & ~split).astype(np.uint8), connectivity=4)
    if n <= 1:
        return cat
    comp = _grow_into(comp, thing)
    out = cat.copy()
    for k in range(1, n):
        m = comp == k
        votes = np.bincount(cat[m], minlength=probs.shape[0])
        present = [int(c) for c in np.argsort(votes)[::-1] if votes[c] > 0]
        if len(present) < 2:
            continue
        top = m & (cat == present[0])
        for c in present[1:]:
            other = m & (cat == c)
            if probs[c][top].mean() > CONFUSED_P and probs[present[0]][other].mean() > CONFUSED_P:
                out[other] = present[0]
    return out


def _drop_fragments(instances: list[Instance]) -> list[Instance]:
    """Pieces under FRAGMENT_AREA of the largest instance of their category: stray bits of an object the network
    split off (two real objects of a kind differ far less in image area on a table seen from these cameras)."""
    largest: dict[int, int] = {}
    for inst in instances:
        largest[inst.category] = max(largest.get(inst.category, 0), int(inst.mask.sum()))
    return [i for i in instances if i.mask.sum() >= FRAGMENT_AREA * largest[i.category]]


def _depth_edges(depth_m: np.ndarray) -> np.ndarray:
    """Pixels next to a depth jump: where one object ends in front of another of the same category."""
    d = np.nan_to_num(depth_m.astype(np.float32), nan=0.0, posinf=10.0)
    gx = np.abs(np.diff(d, axis=1, append=d[:, -1:]))
    gy = np.abs(np.diff(d, axis=0, append=d[-1:, :]))
    jump = np.maximum(gx, gy)
    return jump > np.maximum(DEPTH_EDGE_M, 0.02 * d)


def _grow_into(comp: np.ndarray, region: np.ndarray, iterations: int = 4) -> np.ndarray:
    """Give the region's pixels cut away as boundary back to the neighbouring component (a few pixels deep)."""
    comp = comp.astype(np.int32)
    kernel = np.ones((3, 3), np.uint8)
    for _ in range(iterations):
        free = region & (comp == 0)
        if not free.any():
            break
        grown = cv2.dilate(comp.astype(np.float32), kernel).astype(np.int32)
        comp = np.where(free & (grown > 0), grown, comp)
    return comp


def _centroid_xy(mask: np.ndarray, frame: CameraFrame) -> np.ndarray:
    vs, us = np.nonzero(mask)
    pts = frame.backproject(us.astype(float), vs.astype(float), frame.depth_m[vs, us])
    return np.median(pts[:, :2], axis=0)
