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
from scipy import ndimage

from ..colors import BASE_COLOURS, normalise_colours
from ..detection import Detection
from ..frame import CameraFrame
from ..naming import class_members, own_noun_prompts
from ..pixels import mask_pixels
from ..qualifiers import anchor_apart, on_side, relation_holds, ruled_out_parts, split_qualifier, split_relation
from ..quantiles import percentile, percentiles, percentiles_of_sorted
from ..sim_segmenter import calibrated_score, mask_centroid_xy, pick_by_qualifier
from ..text_encoder import SHARED_ENCODER, TextEncoder
from . import patch_classifier
from .categories import CATEGORIES, CATEGORY_INDEX, COLOURS, ROBOT, TABLE
from .category_names import contradicted, lone_noun_categories
from .drawers import below_cabinet_top, centred_on_handle
from .frozen import frozen_forward
from .heap import keep_freed_memory
from .layers import is_stacked, layer_mask, median_height_m, split_layers
from .pieces import support_of, voxel_components, without_strays
from .refine import grow_by_depth

WEIGHTS = "weights/learned_segmenter.pt"  # package data, next to MODEL_CARD.md
HEAD_NOUN_BONUS = 0.08
REGION_WORDS = {"layer", "level", "tier", "section", "part", "portion"}  # a region of the noun before them
MATERIAL_WORDS = {"wooden", "wood", "metal", "plastic", "ceramic", "wicker"}  # not colour filters
SECOND_LOOK_P = 0.85  # the patch classifier's probability that overrules the per-pixel network's category
SECOND_LOOK_FAIR_P = 0.5  # ... or this much, when it gives the network's category less than IMPLAUSIBLE_P
IMPLAUSIBLE_P = 0.05
GROW_MASKS = True  # refine whole objects' masks by depth at camera resolution (refine.py)
OTHER_DROP_P = 0.5  # a group blob the patch classifier calls "other" with more than this is no group member
MIN_INSTANCE_SCORE = 0.3  # instances the network is less sure of are dropped (stray pixels, table edges)
FRAGMENT_AREA = 0.15
BOUNDARY_PROB = 0.8  # the boundary head is trained with positives weighted 4x: 0.8 is about even odds
PART_REACH_PX = 3  # a part instance must come this close (network pixels) to a pixel of what it is part of
BELOW_TABLE_M = 0.05  # an instance whose median point lies further below the seen table top is off the table
DEPTH_SPREAD_M = 0.25  # mask pixels further than this in depth from the instance's median are another surface
DEPTH_EDGE_M = 0.015  # a depth jump between neighbouring pixels larger than this (and 2 %) splits instances
_NETS: dict[str, Any] = {}
_LOCK = threading.Lock()
_THING = np.array([c.thing for c in CATEGORIES])  # category index -> is an object (not background, table, robot)


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
    `margin` of the best one also count; instances smaller than `min_area_px` (camera pixels) are dropped.
    `patch_weights`: the second-stage patch classifier naming LIBERO's small items (patch_classifier.py);
    False turns that stage off (the per-pixel network's categories stand)."""

    name = "learned"
    privileged = False

    def __init__(
        self,
        weights: str | Path | None = None,
        threshold: float = 0.3,
        margin: float = 0.04,
        min_area_px: int = 40,
        encoder: TextEncoder | None = None,
        patch_weights: str | Path | bool | None = None,
    ):
        self.weights = Path(weights) if weights else default_weights()
        self.patch_weights: Path | None = None
        if patch_weights is not False:
            self.patch_weights = (
                Path(patch_weights) if isinstance(patch_weights, str | Path) else patch_classifier.default_weights()
            )
        keep_freed_memory()  # per-frame arrays reuse the heap's pages (heap.py: ~30-50 ms of page faults per frame)
        self.threshold = threshold
        self.margin = margin
        self.min_area_px = min_area_px
        self.encoder = encoder or SHARED_ENCODER
        self._things = [i for i, c in enumerate(CATEGORIES) if c.thing]
        self._doc_vecs = self.encoder.encode(
            [f"{CATEGORIES[i].name}: {CATEGORIES[i].description}" for i in self._things]
        )
        # per frame: its RGB array (held, so that its id is not reused while cached) and its instances
        self._cache: dict[tuple, tuple[np.ndarray, list[Instance]]] = {}
        self._grounded: dict[str, tuple[dict[int, float], set[str]]] = {}  # prompt text -> `ground`

    # -- grounding ---------------------------------------------------------------------------------------------
    def ground(self, text: str) -> tuple[dict[int, float], set[str]]:
        """(category index -> cosine for the categories a prompt names, colours it asks for). Colour words are
        taken out before matching the category (categories carry no colour); a trailing instance number
        ("bowl 2") is no visual property and is ignored. Words alone decide it, so it is worked out once per
        text (every frame and view asks again; the naming rules run against every category)."""
        if text not in self._grounded:
            self._grounded[text] = self._ground(text)
        named, colours = self._grounded[text]
        return dict(named), set(colours)

    def _ground(self, text: str) -> tuple[dict[int, float], set[str]]:
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
        # a word of the category's own kind stands for its noun ("brick" for a block, "basin" for a bowl): the
        # category scores at least as the prompt with its noun in that word's place would (as the sim oracle does)
        own = own_noun_prompts(core, [CATEGORIES[i].name for i in self._things])
        if own:
            vecs = self.encoder.encode(list(own.values()))
            for k, v in zip(own, vecs):
                cos[k] = max(cos[k], float(self._doc_vecs[k] @ v))
        # the head noun: the last word, unless it names a region of the thing before it ("cabinet drawer layer"
        # is a drawer); an unknown last word stays the head ("cabinet drawer grip" is a handle, not a drawer)
        words_core = core.split()
        head = words_core[-2] if len(words_core) > 1 and words_core[-1] in REGION_WORDS else words_core[-1]
        scores = {}
        for i, c in zip(self._things, cos.tolist()):
            name = CATEGORIES[i].name
            if head == name.split()[-1] or head.rstrip("s") == name.split()[-1]:
                c += HEAD_NOUN_BONUS
            scores[i] = c
        # a lone noun names each category it may mean alike: two sauces in view are several, not the likelier one
        named = lone_noun_categories(core)
        if named:
            top = max(scores[i] for i in named)
            return ({i: top for i in named} if top >= self.threshold else {}), colours
        # a word for a class ("the dairy product", "the appliance") names each category WordNet files under it alike
        members = class_members(core, [CATEGORIES[i].name for i in self._things])
        if members:
            named = {self._things[k] for k in members if not contradicted(core, self._things[k])}
            top = max([self.threshold] + [scores[i] for i in named])
            return {i: top for i in named}, colours
        scores = {i: s for i, s in scores.items() if not contradicted(core, i)}
        if not scores:
            return {}, colours
        best = max(scores.values())
        return {i: s for i, s in scores.items() if s >= self.threshold and s >= best - self.margin}, colours

    # -- pixels -> instances -----------------------------------------------------------------------------------
    def predict(
        self, frame: CameraFrame
    ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """At network resolution (the frame shrunk by the network's factor): category index, its probability,
        boundary probability, colour logits (h, w, n_colours; see `_colour_of`), depth (m) per pixel, and the category
        probabilities (h, w, n_categories): channels last, the network's own layout, so that one pixel's
        probabilities are contiguous (softmax and argmax over a leading channel axis took several times longer).

        Probabilities (both arrays) are computed only on pixels whose category is an object (`Category.thing`) and
        are 0 elsewhere: every reader looks at object pixels alone, which are about an eighth of a LIBERO frame
        (the whole-frame softmax was ~8 ms of a ~100 ms frame). The category is the logits' argmax, which is the
        probabilities' argmax."""
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
                cat_logits, bnd_logit, col_logits = net.split(frozen_forward(net, x))
                cat_logits[:, net.n_trained :] = -torch.inf  # categories appended after these weights were trained
                # channels last (the graph's output layout): one pixel's logits are contiguous, so the argmax and
                # the softmax run along memory
                # the graph's output is channels last with the boundary and colour channels beside these: one
                # copy packs each pixel's category logits together, and numpy's argmax along packed rows is the
                # fastest of the ways measured (strided: 1.6x slower)
                logits = np.ascontiguousarray(cat_logits[0].permute(1, 2, 0).numpy())
                h, w, n_cat = logits.shape
                cat = logits.argmax(-1).astype(np.int32)
                on_things = np.flatnonzero(_THING[cat])
                rows = torch.softmax(torch.from_numpy(logits.reshape(h * w, n_cat)[on_things]), -1).numpy()
                probs_hwc = np.zeros((h, w, n_cat), np.float32)
                probs_hwc.reshape(h * w, n_cat)[on_things] = rows
                prob = np.zeros((h, w), np.float32)
                prob.reshape(-1)[on_things] = rows[np.arange(len(on_things)), cat.reshape(-1)[on_things]]
                bnd = np.ascontiguousarray(torch.sigmoid(bnd_logit[0]).numpy())
                col = col_logits[0].permute(1, 2, 0).numpy()  # logits: only instance pixels need probabilities
        finally:
            torch.set_num_threads(threads)
        return cat, prob, bnd, col, depth, probs_hwc

    def instances(self, frame: CameraFrame) -> list[Instance]:
        """Every object instance the network sees in this frame (cached per frame: one prompt set per frame
        usually arrives in several calls). Instances are found at network resolution; each mask is then scaled
        to the frame by nearest pixel (at most a camera pixel off at the edges)."""
        key = (id(frame.rgb), frame.camera, frame.sim_time_s)
        hit = self._cache.get(key)
        if hit is not None and hit[0] is frame.rgb:  # the same array, not a new one where a freed one lived
            return hit[1]
        cat, prob, bnd, col, depth, probs = self.predict(frame)
        H, W = frame.shape
        factor_sq = (H / cat.shape[0]) * (W / cat.shape[1])
        split = (bnd > BOUNDARY_PROB) | _depth_edges(depth)
        cat = _merge_confused(cat, probs, split)
        out: list[Instance] = []
        named_by_patch: set[int] = set()
        if self.patch_weights is not None:
            out.extend(self._group_instances(frame, cat, probs, col, split, factor_sq))
            named_by_patch = set(patch_classifier.GROUP_INDEX.tolist())
        for c in np.unique(cat):
            if not CATEGORIES[c].thing or int(c) in named_by_patch:
                continue
            region = cat == c
            n, comp = cv2.connectedComponents((region & ~split).astype(np.uint8), connectivity=4)
            comp = _grow_into(comp, region)
            if CATEGORIES[c].max_extent_m:
                comp, n = _rejoin(
                    comp, n, CATEGORIES[c].max_extent_m, depth, frame, H // cat.shape[0], CATEGORIES[c].max_height_m
                )
            parents = _anchored(cat, CATEGORIES[c].part_of)
            # each component's box, in one pass: the per-component work below reads only that box (the same
            # pixels in the same order as the whole-frame mask would give)
            for k, box in enumerate(ndimage.find_objects(comp, max_label=n - 1), start=1):
                if box is None:  # a label _rejoin joined into another
                    continue
                m_box = comp[box] == k
                if m_box.sum() * factor_sq < self.min_area_px:
                    continue
                if CATEGORIES[c].part_of and not _on_parent(comp == k, parents, depth):
                    continue  # a handle or knob on nothing: the network's mistake (a label, a bottle's rim)
                score = float(np.median(prob[box][m_box]))
                if score < MIN_INSTANCE_SCORE:
                    continue
                colour = _colour_of(col[box][m_box])
                full = _one_surface_upscaled(m_box, box, frame, (H, W), cat.shape)
                if CATEGORIES[c].proud_m:
                    full = _proud(full, frame, CATEGORIES[c].proud_m)
                if not CATEGORIES[c].part_of:  # a stray in front shifts the keypoint (a short kind's seen top)
                    full = without_strays(full, frame)
                if full.sum() < self.min_area_px:
                    continue
                out.append(Instance(int(c), full, score, colour))
        if self.patch_weights is not None:
            out = self._second_look(out, frame)
        top_z = _table_top_z(cat, frame)  # once: both clean-ups below measure the same table
        out = _absorb_pieces(_grown(out, cat, frame, top_z), frame)
        out = _above_table(_drop_fragments([_standing_part(i, frame) for i in out]), top_z, frame)
        out = _drawers_in_place(_drawers_apart(out, frame), frame)
        if len(self._cache) > 8:
            self._cache.clear()
        self._cache[key] = (frame.rgb, out)
        return out

    def _group_instances(
        self,
        frame: CameraFrame,
        cat: np.ndarray,
        probs: np.ndarray,
        col: np.ndarray,
        split: np.ndarray,
        factor_sq: float,
    ) -> list[Instance]:
        """Instances of the patch classifier's GROUP: the per-pixel network's group pixels (whichever member it
        named) cut into blobs at boundaries and depth edges, each named by the classifier from a camera-resolution
        patch. Score: geometric mean of the blob's median group probability and the classifier's. `probs` and
        `col` (colour logits): (h, w, C) as `predict` gives them."""
        net = patch_classifier.load(self.patch_weights)  # type: ignore[arg-type]  # set when called
        H, W = frame.shape
        region = np.isin(cat, patch_classifier.GROUP_INDEX)
        n, comp = cv2.connectedComponents((region & ~split).astype(np.uint8), connectivity=4)
        comp = _grow_into(comp, region)
        blobs, patches = [], []
        for k, box in enumerate(ndimage.find_objects(comp, max_label=n - 1), start=1):
            if box is None:
                continue
            m_box = comp[box] == k
            if m_box.sum() * factor_sq < self.min_area_px:
                continue
            m = comp == k
            full = _one_surface_upscaled(m_box, box, frame, (H, W), cat.shape)
            for piece in _apart_in_space(full, frame):
                if piece.sum() < self.min_area_px:
                    continue
                p = patch_classifier.patch(frame.rgb, frame.depth_m, piece)
                if p is not None:
                    small = cv2.resize(piece.astype(np.uint8), m.shape[::-1], interpolation=cv2.INTER_NEAREST)
                    blobs.append((m & small.astype(bool) if (m & small.astype(bool)).any() else m, piece))
                    patches.append(p)
        out = []
        for (m, full), p_cls in zip(blobs, patch_classifier.classify(net, patches)):
            if p_cls[patch_classifier.OTHER] > OTHER_DROP_P:
                continue
            best = int(p_cls[: patch_classifier.OTHER].argmax())
            # the blob's summed group probability, on its own pixels only (a whole-frame sum cost ~3 ms per frame)
            mass = probs[m][:, patch_classifier.GROUP_INDEX].sum(-1)
            score = float(np.sqrt(np.median(mass) * p_cls[best]))
            if score < MIN_INSTANCE_SCORE:
                continue
            colour = _colour_of(col[m])
            category = int(patch_classifier.CLASS_CATEGORY[best])
            out.append(Instance(category, full, score, colour))
        return out

    def _second_look(self, instances: list[Instance], frame: CameraFrame) -> list[Instance]:
        """Whole objects the per-pixel network named (GROUP blobs are named by the classifier already) take the
        patch classifier's name when it is confident of another one (a plate standing on a stove that the
        per-pixel network called stove, LIBERO's white ramekin called a bowl)."""
        group = set(patch_classifier.GROUP_INDEX.tolist())
        net = patch_classifier.load(self.patch_weights)  # type: ignore[arg-type]  # set when called
        # a kind the classifier's weights predate (appended since) is never overruled: it cannot be recognised
        known = {CATEGORY_INDEX[c] for c in net.classes[:-1]}
        idx = [
            k
            for k, i in enumerate(instances)
            if i.category not in group and not CATEGORIES[i.category].part_of and i.category in known
        ]
        if not idx:
            return instances
        patches = [patch_classifier.patch(frame.rgb, frame.depth_m, instances[k].mask) for k in idx]
        keep = [(k, p) for k, p in zip(idx, patches) if p is not None]
        probs = patch_classifier.classify(net, [p for _, p in keep])
        out = list(instances)
        renamed = set()
        for (k, _), p_cls in zip(keep, probs):
            best = int(p_cls.argmax())
            own = int(np.flatnonzero(np.equal(patch_classifier.CLASS_CATEGORY, out[k].category))[0])
            # overruled when the classifier is sure of another name, or fairly sure of it while finding the
            # network's name implausible (a bowl on a stove that the per-pixel network painted as stove)
            sure = p_cls[best] >= SECOND_LOOK_P or (p_cls[best] >= SECOND_LOOK_FAIR_P and p_cls[own] < IMPLAUSIBLE_P)
            if best == patch_classifier.OTHER or not sure:
                continue
            category = int(patch_classifier.CLASS_CATEGORY[best])
            if category != out[k].category:
                i = out[k]
                out[k] = Instance(category, i.mask, float(np.sqrt(i.score * p_cls[best])), i.colour)
                renamed.add(category)
        return _join_renamed(out, renamed, frame)

    # -- the Segmenter protocol --------------------------------------------------------------------------------
    def names_in(self, frame: CameraFrame) -> list[str]:
        """What this frame shows, once per instance, by the network's own category names (no colours: they are
        supervised only for some objects), parts included as the sim oracle lists them (a drawer, its handle): the
        planner checks every thing an instruction names against this list ("the top of the drawer" needs a drawer
        in it). Camera-only, like everything here: for a planner that says what the scene holds."""
        return sorted(CATEGORIES[i.category].name for i in self.instances(frame))

    def segment(self, frame: CameraFrame, prompts: Sequence[str]) -> list[Detection]:
        out: list[Detection] = []
        for prompt in prompts:
            head, relation, anchors = split_relation(prompt)
            if relation is not None:
                out.extend(self._related(frame, prompt, head, relation, anchors))
                continue
            unlike = re.fullmatch(r"(.+?) not (.+)", prompt.strip().lower())
            if unlike:  # "block not blue", "bowl not leftmost": every instance but those the negated words pick
                core, said = unlike.group(1), unlike.group(2)
                ruled_out = {
                    d.detail["instance"]
                    for part in ruled_out_parts(said)  # "box not cream cheese nor chocolate pudding": both
                    for d in self.segment(frame, [f"{part} {core}"])
                }
                out.extend(
                    Detection(prompt, prompt, d.mask, d.score, d.camera, False, {**d.detail, "unlike": said})
                    for d in self.segment(frame, [core])
                    if d.detail["instance"] not in ruled_out
                )
                continue
            qualifier, core = split_qualifier(prompt)
            if re.search(r"\bof\b", prompt):  # "the top drawer of the cabinet": the drawer is the target
                core = split_qualifier(re.split(r"\bof\b", prompt)[0])[1] or core
            dets = self._matches(frame, prompt, core)
            if is_stacked(qualifier) and dets and all(d.detail["category"] == "drawer" for d in dets):
                dets = self._drawer_layer(frame, dets, qualifier)  # type: ignore[arg-type]  # is_stacked: a str
            elif qualifier and len(dets) > 1:
                middle = self._table_middle_xy(frame) if qualifier == "middle" else None
                dets = [pick_by_qualifier(dets, frame, qualifier, table_middle_xy_m=middle)]
            out.extend(dets)
        return out

    def _table_middle_xy(self, frame: CameraFrame) -> np.ndarray | None:
        """The middle of the table (m, world xy) as this frame shows it: the mean centroid of every thing seen on
        it ("the middle bowl" of two is the one nearer it, as the sim oracle reads it from its object ids)."""
        seen = [mask_centroid_xy(i.mask, frame) for i in self.instances(frame) if CATEGORIES[i.category].thing]
        return np.mean(seen, axis=0) if seen else None

    def _matches(self, frame: CameraFrame, prompt: str, core: str) -> list[Detection]:
        cats, colours = self.ground(core)
        if not cats:
            return []
        seen = {i.category for i in self.instances(frame)}
        best = max(cats, key=cats.__getitem__)
        # the part the prompt names best is not in view: its parent's instances here only stand in for it
        stand_ins = set() if best in seen else {CATEGORY_INDEX[p] for p in CATEGORIES[best].part_of}
        if best in seen:  # the part itself is here: what it is part of is no answer ("drawer grip": not the drawer)
            cats = {c: v for c, v in cats.items() if CATEGORIES[c].name not in CATEGORIES[best].part_of}
        if not seen & set(cats):
            cats = _parent_named(cats, core) or cats
        dets = []
        for k, inst in enumerate(self.instances(frame)):
            if inst.category not in cats or (colours and inst.colour not in colours):
                continue
            # grounding and pixel confidence together; their geometric mean keeps 0.5 as "as sure as not"
            score = float(np.sqrt(calibrated_score(cats[inst.category], self.threshold) * inst.score))
            detail: dict[str, Any] = {"category": CATEGORIES[inst.category].name, "colour": inst.colour, "instance": k}
            if inst.category in stand_ins:  # fused_evidence prefers a view that saw the part itself
                detail["stand_in_for_part"] = True
            dets.append(Detection(prompt, prompt, inst.mask, round(score, 4), frame.camera, False, detail))
        return dets

    def _drawer_layer(self, frame: CameraFrame, dets: list[Detection], qualifier: str) -> list[Detection]:
        """The drawer a stacked qualifier names, cut from the drawer fronts by its handle's height (layers.py);
        the qualifier among the drawer instances when no handle is seen."""
        handles = [i.mask for i in self.instances(frame) if i.category == CATEGORY_INDEX["drawer handle"]]
        union = np.logical_or.reduce([d.mask for d in dets])
        mask = layer_mask(union, handles, qualifier, frame)
        if mask is None or mask.sum() < self.min_area_px:
            return [pick_by_qualifier(dets, frame, qualifier)] if len(dets) > 1 else dets
        best = max(dets, key=lambda d: d.score)
        return [
            Detection(
                best.prompt, best.prompt, mask, best.score, frame.camera, False, {**best.detail, "layer": qualifier}
            )
        ]

    def _related(
        self, frame: CameraFrame, prompt: str, head: str, relation: str, anchors: list[str]
    ) -> list[Detection]:
        """Instances of `head`; when several, the one nearest the anchor objects (their midpoint for "between"),
        or the farthest when negated; "the table center" is the middle of every instance in view. Each detection
        records whether it stands in the relation to the anchors this view saw (detail "relation_holds"; absent
        when the view saw no anchor): a view that sees only the wrong bowl must not outvote one that sees both."""
        negated = relation.startswith("not ")
        dets = self.segment(frame, [head])
        found: list[tuple[np.ndarray, float]] = []
        for a in anchors:
            cands, dets = anchor_apart(dets, self.segment(frame, [a]), "instance")
            if cands:
                found.append(_footprint_xy(max(cands, key=lambda d: d.score).mask, frame))
        centres = [c for c, _ in found]
        if len(dets) > 1 and not found and any(w in a for a in anchors for w in ("center", "centre", "middle")):
            centres = [np.mean([_centroid_xy(i.mask, frame) for i in self.instances(frame)], axis=0)]
        if len(dets) > 1 and centres:
            target = np.mean(centres, axis=0)
            sided = [d for d in dets if on_side(relation, _centroid_xy(d.mask, frame), target) != negated]
            dets = sided or dets  # "the bowl left of the plate": of those on that side, the nearest
            pick = max if negated and not sided else min
            dets = [pick(dets, key=lambda d: float(np.linalg.norm(_centroid_xy(d.mask, frame) - target)))]
        out = []
        for d in dets:
            detail: dict[str, Any] = {**d.detail, "relation_anchors": anchors}
            if len(found) == len(anchors):
                detail["relation_holds"] = relation_holds(relation, _centroid_xy(d.mask, frame), found)
            out.append(Detection(prompt, prompt, d.mask, d.score, d.camera, False, detail))
        return out


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


def _colour_of(logits: np.ndarray) -> str:
    """An instance's colour name from its pixels' colour logits (n, n_colours): the largest mean probability
    after the "none" class (index 0). Softmax only on these pixels (over the whole frame it cost ~8 ms), in numpy:
    torch's small calls here ran on the process's thread pool, whose synchronisation cost more than the work."""
    e = np.exp(logits - logits.max(1, keepdims=True))
    p = e / e.sum(1, keepdims=True)
    return COLOURS[1 + int(p[:, 1:].mean(0).argmax())]


def _merge_confused(cat: np.ndarray, probs: np.ndarray, split: np.ndarray) -> np.ndarray:
    """Within one object blob (connected object pixels, cut at boundaries and depth edges), two categories the
    network hesitates between on each other's pixels (e.g. ketchup / tomato sauce bottles) are one object of the
    category with more pixels; categories it tells apart (a block on a plate) stay separate instances. `probs`:
    (h, w, n_categories) category probabilities."""
    thing = _THING[cat]
    n, comp = cv2.connectedComponents((thing & ~split).astype(np.uint8), connectivity=4)
    if n <= 1:
        return cat
    comp = _grow_into(comp, thing)
    out = cat.copy()
    # each blob read inside its bounding box (the same pixels in the same order as the whole-frame mask gives)
    for k, box in enumerate(ndimage.find_objects(comp, max_label=n - 1), start=1):
        if box is None:
            continue
        m, cat_box = comp[box] == k, cat[box]
        votes = np.bincount(cat_box[m], minlength=probs.shape[-1])
        present = [int(c) for c in np.argsort(votes)[::-1] if votes[c] > 0]
        if len(present) < 2:
            continue
        top = m & (cat_box == present[0])
        for c in present[1:]:
            other = m & (cat_box == c)
            if probs[(*box, c)][top].mean() > CONFUSED_P and probs[(*box, present[0])][other].mean() > CONFUSED_P:
                out[box][other] = present[0]
    return out


def _absorb_pieces(instances: list[Instance], frame: CameraFrame) -> list[Instance]:
    """Instances smaller than their kind can be (Category.min_extent_m) that stand on a whole object joined to
    that object's mask (pieces.py: the stove knob's fin read as a wine bottle). Where the object's kind has one
    kind of part (a stove: its knob), the piece is also that part: the network had named it after a look-alike
    because it did not know it as the part."""
    out: list[Instance | None] = list(instances)
    parts: list[Instance] = []
    for i, inst in enumerate(instances):
        kind = CATEGORIES[inst.category]
        if not kind.min_extent_m:
            continue
        wholes = [j for j, o in enumerate(out) if o is not None and j != i and not CATEGORIES[o.category].part_of]
        k = support_of(inst.mask, [out[j].mask for j in wholes], frame, kind.min_extent_m)  # type: ignore[union-attr]
        if k is None:
            continue
        s = out[wholes[k]]
        assert s is not None
        out[wholes[k]], out[i] = Instance(s.category, s.mask | inst.mask, s.score, s.colour), None
        part_kinds = [c for c, p in enumerate(CATEGORIES) if CATEGORIES[s.category].name in p.part_of]
        if len(part_kinds) == 1:
            parts.append(Instance(part_kinds[0], inst.mask, inst.score, inst.colour))
    return [o for o in out if o is not None] + parts


def _drawers_apart(instances: list[Instance], frame: CameraFrame) -> list[Instance]:
    """Each drawer instance cut into one per handle layer on it (layers.split_layers): the network paints a
    cabinet's stacked fronts as one region (they touch, share a colour and a depth) but sees each handle apart."""
    drawer, handle = CATEGORY_INDEX["drawer"], CATEGORY_INDEX["drawer handle"]
    handles = [i.mask for i in instances if i.category == handle]
    if len(handles) < 2:
        return instances
    out = []
    for inst in instances:
        if inst.category != drawer:
            out.append(inst)
            continue
        on_it = [h for h in handles if _touches(h, inst.mask, reach_px=2 * PART_REACH_PX)]
        out.extend(Instance(drawer, m, inst.score, inst.colour) for m in split_layers(inst.mask, on_it, frame))
    return out


def _drawers_in_place(instances: list[Instance], frame: CameraFrame) -> list[Instance]:
    """Each drawer's mask kept below the top of the cabinet it touches and centred on its handle (drawers.py):
    the network's drawer region spills onto the cabinet's face and top around it."""
    drawer, handle, cabinet = (CATEGORY_INDEX[n] for n in ("drawer", "drawer handle", "cabinet"))
    cabinets = [i.mask for i in instances if i.category == cabinet]
    handles = [i.mask for i in instances if i.category == handle]
    out = []
    for inst in instances:
        if inst.category != drawer:
            out.append(inst)
            continue
        mask = below_cabinet_top(inst.mask, [c for c in cabinets if _touches(c, inst.mask)], frame)
        on_it = [h for h in handles if _touches(h, mask, reach_px=2 * PART_REACH_PX)]
        z = median_height_m(mask, frame)
        if on_it and z is not None:  # the handle at this drawer's height (stacked fronts: one each, after layers)
            own = min(on_it, key=lambda h: abs((median_height_m(h, frame) or np.inf) - z))
            mask = centred_on_handle(mask, own, frame)
        out.append(Instance(drawer, mask, inst.score, inst.colour))
    return out


def _drop_fragments(instances: list[Instance]) -> list[Instance]:
    """Pieces under FRAGMENT_AREA of the largest instance of their category: stray bits of an object the network
    split off (two real objects of a kind differ far less in image area on a table seen from these cameras)."""
    largest: dict[int, int] = {}
    areas = [int(np.count_nonzero(inst.mask)) for inst in instances]
    for inst, area in zip(instances, areas):
        largest[inst.category] = max(largest.get(inst.category, 0), area)
    return [i for i, area in zip(instances, areas) if area >= FRAGMENT_AREA * largest[i.category]]


SUPPORT_BAND_M = 0.006  # points this close above a blob's lowest level are on its support (the floor), not it
SPACE_VOXEL_M = 0.01  # objects whose visible surfaces are further apart than this in 3D are separate


def _apart_in_space(mask: np.ndarray, frame: CameraFrame) -> list[np.ndarray]:
    """The mask split into the parts whose 3D points are connected (26-neighbour voxels of SPACE_VOXEL_M): a can
    standing in front of a carton overlaps it in the image with no depth edge the network marks, but the two never
    touch in space. Pieces under 10 % of the mask are dropped (stray pixels)."""

    vs, us = mask_pixels(mask)
    z = frame.depth_m[vs, us]
    ok = np.isfinite(z) & (z > 0)
    if ok.sum() < 20:
        return [mask]
    vs, us = vs[ok], us[ok]
    pts = frame.backproject(us.astype(float), vs.astype(float), z[ok])
    # pixels spilled onto the floor or table join everything standing on it: leave out the points at the blob's
    # lowest level when the blob rises well above it (a flat item alone is all "lowest level")
    low, high = percentiles(pts[:, 2], (2, 98))
    above = pts[:, 2] > low + SUPPORT_BAND_M
    if high - low > 3 * SUPPORT_BAND_M and above.mean() > 0.3:
        vs, us, pts = vs[above], us[above], pts[above]
    lab = voxel_components(pts, SPACE_VOXEL_M)
    if lab is None or lab.max() <= 1:  # spread over meters (other filters handle it), or all one piece
        return [mask]
    n = int(lab.max())
    out = []
    for k in range(1, n + 1):
        sel = lab == k
        if sel.sum() >= 0.1 * len(lab):
            piece = np.zeros_like(mask)
            piece[vs[sel], us[sel]] = True
            out.append(piece)
    return out or [mask]


def _join_renamed(instances: list[Instance], categories: set[int], frame: CameraFrame) -> list[Instance]:
    """After renaming, a renamed piece and another instance of its new category that touch in the image are one
    object when together no wider than one can be (Category.max_extent_m): the front of a bowl the per-pixel
    network took for the wine rack behind it, and the bowl's back it got right."""
    out = list(instances)
    kernel = np.ones((5, 5), np.uint8)
    for c in categories:
        limit = CATEGORIES[c].max_extent_m
        if not limit:
            continue
        merged = True
        while merged:
            merged = False
            same = [k for k, i in enumerate(out) if i.category == c]
            for a in same:
                grown = cv2.dilate(out[a].mask.astype(np.uint8), kernel).astype(bool)
                for b in same:
                    if b == a or not (grown & out[b].mask).any():
                        continue
                    union = out[a].mask | out[b].mask
                    if _xy_width(union, frame) <= limit:
                        keep = out[a] if out[a].mask.sum() >= out[b].mask.sum() else out[b]
                        out[a] = Instance(c, union, max(out[a].score, out[b].score), keep.colour)
                        del out[b]
                        merged = True
                        break
                if merged:
                    break
    return out


def _xy_width(mask: np.ndarray, frame: CameraFrame, n: int = 800) -> float:
    """Widest extent (m) of the mask's 3D points along world x or y (2nd to 98th percentile)."""
    vs, us = mask_pixels(mask)
    step = max(1, len(vs) // n)
    vs, us = vs[::step], us[::step]
    z = frame.depth_m[vs, us]
    ok = np.isfinite(z) & (z > 0)
    if ok.sum() < 3:
        return 0.0
    xy = frame.backproject(us[ok].astype(float), vs[ok].astype(float), z[ok])[:, :2]
    lo, hi = percentiles(xy, (2, 98))
    return float((hi - lo).max())


def _parent_named(cats: dict[int, float], prompt: str) -> dict[int, float]:
    """For a prompt naming a part the network sees nowhere ("stove knob" on a stove whose knob it never learned),
    the part's parent when the prompt names it too: the part is on it, and the parent is what can be seen (as the
    `sim` oracle, which has no knob on that stove either, resolves such a prompt to the stove)."""
    words = set(_words(prompt))
    out = {}
    for c, cos in cats.items():
        for parent in CATEGORIES[c].part_of:
            if parent.split()[-1] in words:
                out[CATEGORY_INDEX[parent]] = cos
    return out


def _rejoin(
    comp: np.ndarray,
    n: int,
    max_extent_m: float,
    depth_m: np.ndarray,
    frame: CameraFrame,
    factor: int,
    max_height_m: float = 0.0,
) -> tuple[np.ndarray, int]:
    """Join touching components of one category while together they are no wider than one object can be.

    A depth edge splits a bowl's near rim from its bottom and far rim (one object, centimetres apart in depth);
    two bowls side by side are split the same way. Their sizes tell them apart: the pieces of one bowl together
    span at most a bowl's width in the world's xy, two bowls span about two. For a short kind (`max_height_m`, m)
    the width is measured on the joined pieces' upper half-height band only: a bowl on the stove spills pixels onto
    the stove top around it, which made its own two halves look wider than a bowl and kept them apart. Network-
    resolution components and depth; pixel (v, u) is camera pixel (v * factor, u * factor)."""
    xy: dict[int, np.ndarray] = {}
    boxes: dict[int, tuple[int, int, int, int]] = {}
    # every component's pixels in one pass (a stable sort keeps each one's row-major order): a frame of many small
    # components made `comp == k` per component the slowest step of a LIBERO frame
    vs_all, us_all = mask_pixels(comp > 0)
    labels = comp[vs_all, us_all]
    order = np.argsort(labels, kind="stable")
    starts = np.searchsorted(labels[order], np.arange(1, n + 1))
    for k in range(1, n):
        idx = order[starts[k - 1] : starts[k]]
        vs, us = vs_all[idx], us_all[idx]
        z = depth_m[vs, us]
        ok = np.isfinite(z) & (z > 0)
        if ok.sum() >= 3:
            xy[k] = frame.backproject(us[ok] * float(factor), vs[ok] * float(factor), z[ok])
            boxes[k] = (int(vs.min()), int(vs.max()), int(us.min()), int(us.max()))
    if len(xy) < 2:
        return comp, n
    kernel = np.ones((5, 5), np.uint8)
    owner = {k: k for k in xy}

    def root(k: int) -> int:
        while owner[k] != k:
            k = owner[k]
        return k

    # per root, for a kind measured on all its points: its x and y, each column sorted. A pair's joined columns
    # are then one stable sort away (a merge of two sorted runs) and its percentiles are read by index: the same
    # numbers as partitioning the joined points, at a fraction of the cost (~2,500 pairs per 20 LIBERO frames)
    sorted_xy: dict[int, np.ndarray] = {}

    def joined_sorted(a: int, b: int) -> np.ndarray:
        for k in (a, b):
            if k not in sorted_xy:
                sorted_xy[k] = np.sort(xy[k][:, :2], axis=0)
        return np.sort(np.concatenate([sorted_xy[a], sorted_xy[b]]), axis=0, kind="stable")

    def width(a: int, b: int) -> float:
        if max_height_m:  # measured on the joined points' upper band, which only the joined points define
            pts = np.concatenate([xy[a], xy[b]])
            upper = pts[pts[:, 2] > percentile(pts[:, 2], 98) - 0.5 * max_height_m]
            pts = upper if len(upper) >= 3 else pts
            lo, hi = percentiles(pts[:, :2], (2, 98))
        else:
            lo, hi = percentiles_of_sorted(joined_sorted(a, b), (2, 98))
        return float((hi - lo).max())

    touching = set()
    H, W = comp.shape
    for k in xy:
        r0, r1, c0, c1 = boxes[k]
        r0, c0, r1, c1 = max(0, r0 - 2), max(0, c0 - 2), min(H, r1 + 3), min(W, c1 + 3)  # the 5x5 dilation's reach
        crop = comp[r0:r1, c0:c1]
        near = np.unique(crop[cv2.dilate((crop == k).astype(np.uint8), kernel).astype(bool)])
        touching |= {(min(k, j), max(k, j)) for j in near.tolist() if j in xy and j != k}
    widths: dict[tuple[int, int], float] = {}  # joined width per pair of current roots (dropped when one grows)
    while True:  # the narrowest join first: a bowl's own pieces before a neighbour's
        best: tuple[float, int, int] | None = None
        for k, j in touching:
            a, b = root(k), root(j)
            if a != b:
                if (a, b) not in widths:
                    widths[(a, b)] = width(a, b)
                w = widths[(a, b)]
                if w <= max_extent_m and (best is None or w < best[0]):
                    best = (w, a, b)
        if best is None:
            break
        _, a, b = best
        owner[b] = a
        if not max_height_m:  # the joined root's columns, sorted; b is no root any more
            sorted_xy[a] = joined_sorted(a, b)
            del sorted_xy[b]
        xy[a] = np.concatenate([xy[a], xy[b]])
        widths = {pair: w for pair, w in widths.items() if a not in pair and b not in pair}
    lut = np.arange(n, dtype=comp.dtype)
    for k in owner:
        lut[k] = root(k)
    return lut[comp], n


PROUD_SLICE_PX = 6  # width (camera pixels) of the slices across a part's length that are compared apart


def _proud(mask: np.ndarray, frame: CameraFrame, proud_m: float) -> np.ndarray:
    """The pixels of a part's mask within proud_m behind the nearest ones (5th percentile depth, not the very
    nearest: a stray pixel on something in front would move it) of their slice across the part's length (its
    longer image axis). Sliced because a handle seen at an angle recedes along its length by more than proud_m:
    against one nearest depth for the whole mask, a LIBERO handle seen by agentview lost its far half."""
    vs, us = mask_pixels(mask)
    d = frame.depth_m[vs, us]
    ok = np.isfinite(d) & (d > 0)
    if ok.sum() < 10:
        return mask
    pts = np.stack([us, vs], 1).astype(float)
    centred = pts - pts.mean(0)
    axis = np.linalg.eigh(centred.T @ centred)[1][:, -1]  # the longer image axis
    slice_of = np.floor(centred @ axis / PROUD_SLICE_PX).astype(int)
    keep_px = np.zeros(len(vs), bool)
    for k in np.unique(slice_of[ok]):
        here = ok & (slice_of == k)
        near = float(percentile(d[here], 5))
        keep_px |= here & (d <= near + proud_m)
    keep = np.zeros_like(mask)
    keep[vs[keep_px], us[keep_px]] = True
    return keep if keep.sum() >= 0.2 * mask.sum() else mask


def _standing_part(inst: Instance, frame: CameraFrame) -> Instance:
    """The instance without the mask pixels more than its category's max_height_m below its seen top (98th
    percentile of world z): what it stands on, painted with its category. Kept whole when that would leave less
    than a fifth of the mask (then the "top" itself is doubtful)."""
    limit = CATEGORIES[inst.category].max_height_m
    if not limit:
        return inst
    vs, us = mask_pixels(inst.mask)
    height = frame.height_map_m[vs, us]
    ok = np.isfinite(height)  # NaN where the depth is missing
    if ok.sum() < 10:
        return inst
    low = ok & (height < float(percentile(height[ok], 98)) - limit)
    if not low.any() or (~low).sum() < 0.2 * len(vs):
        return inst
    mask = inst.mask.copy()
    mask[vs[low], us[low]] = False
    return Instance(inst.category, mask, inst.score, inst.colour)


def _above_table(instances: list[Instance], top: float | None, frame: CameraFrame) -> list[Instance]:
    """Objects stand on the table or above it: an instance whose median point lies BELOW_TABLE_M under the table
    top the network sees in this frame (`top`, world z in m: `_table_top_z`) is the wall or floor behind,
    mislabelled (a frame with no table in view, top None, e.g. a wrist close-up, keeps everything)."""
    if top is None:
        return instances
    keep = []
    for inst in instances:
        z = median_height_m(inst.mask, frame)
        if z is None or z >= top - BELOW_TABLE_M:
            keep.append(inst)
    return keep


def _table_top_z(cat: np.ndarray, frame: CameraFrame) -> float | None:
    """World height (m) of the table top the network sees in this frame; None when too little table is in view."""
    table = cat == TABLE
    if table.sum() < 50:
        return None
    full = cv2.resize(table.astype(np.uint8), (frame.shape[1], frame.shape[0]), interpolation=cv2.INTER_NEAREST)
    return median_height_m(full.astype(bool), frame)


def _grown(instances: list[Instance], cat: np.ndarray, frame: CameraFrame, table_top_z: float | None) -> list[Instance]:
    """Whole objects' masks grown at camera resolution into what the network called background or table where
    the depth continues their surface above the table top (`table_top_z`, world m: `_table_top_z`; refine.py:
    thin necks lost at half resolution)."""
    top = table_top_z if GROW_MASKS else None
    if top is None:
        return instances
    H, W = frame.shape
    free = cv2.resize(
        np.isin(cat, [c for c, k in enumerate(CATEGORIES) if not k.thing and c != ROBOT]).astype(np.uint8),
        (W, H),
        interpolation=cv2.INTER_NEAREST,
    ).astype(bool)
    depth, height = frame.depth_m, frame.height_map_m  # height NaN where depth is missing: never grown into
    out = []
    for i in instances:
        kind = CATEGORIES[i.category]
        # parts have their own clean-up (_proud); short kinds (max_height_m: bowls, plates) have no thin top to
        # lose, and grown they spread onto what they stand next to
        out.append(
            i
            if kind.part_of or kind.max_height_m
            else Instance(i.category, grow_by_depth(i.mask, free, depth, height, top), i.score, i.colour)
        )
    return out


def _anchored(cat: np.ndarray, names: tuple[str, ...]) -> np.ndarray:
    """Pixels of the named categories, keeping of a category that is itself a part (a drawer) only the connected
    pieces that touch what it is part of (the cabinet)."""
    out = np.zeros(cat.shape, bool)
    for name in names:
        region = cat == CATEGORY_INDEX[name]
        part_of = CATEGORIES[CATEGORY_INDEX[name]].part_of
        if part_of and region.any():
            base = np.isin(cat, [CATEGORY_INDEX[p] for p in part_of])
            n, comp = cv2.connectedComponents(region.astype(np.uint8), connectivity=8)
            region = np.isin(comp, [k for k in range(1, n) if _touches(comp == k, base)])
        out |= region
    return out


PART_GAP_M = 0.08  # a part this far in depth from every parent pixel beside it is seen past the parent, not on it


def _on_parent(mask: np.ndarray, parents: np.ndarray, depth_m: np.ndarray) -> bool:
    """Whether a part's pixels (network resolution) touch its parent's in the image AND some parent pixel beside
    them lies within PART_GAP_M of the part's median depth: the handle-coloured fringe round a small handle seen
    from afar is floor 30 cm behind the cabinet, touching it only in the image. (Some, not most: from the side,
    the cabinet's side face beside a handle on its front is up to its depth nearer the camera.)"""
    k = np.ones((2 * PART_REACH_PX + 1, 2 * PART_REACH_PX + 1), np.uint8)
    beside = cv2.dilate(mask.astype(np.uint8), k).astype(bool) & parents  # what _touches tests, kept for depth
    if not beside.any():
        return False
    d_part, d_parent = depth_m[mask], depth_m[beside]
    d_part, d_parent = d_part[np.isfinite(d_part)], d_parent[np.isfinite(d_parent)]
    if not len(d_part) or not len(d_parent):
        return True
    return float(np.abs(d_parent - np.median(d_part)).min()) < PART_GAP_M


def _touches(mask: np.ndarray, other: np.ndarray, reach_px: int = PART_REACH_PX) -> bool:
    """Whether `mask` comes within `reach_px` pixels of any pixel of `other`."""
    k = np.ones((2 * reach_px + 1, 2 * reach_px + 1), np.uint8)
    return bool((cv2.dilate(mask.astype(np.uint8), k).astype(bool) & other).any())


def _one_surface_upscaled(
    m_box: np.ndarray, box: tuple[slice, slice], frame: CameraFrame, full_shape: tuple[int, int], net_shape: tuple
) -> np.ndarray:
    """`_one_surface` of the network-resolution mask `m_box` (the part of it inside `box`, a component's bounding
    slices) scaled up to the frame by nearest pixel: exactly what scaling the whole-frame mask with cv2's
    INTER_NEAREST and applying `_one_surface` gives, computed inside the box only. Where the frame is not an
    exact multiple of the network's size, the whole-frame way."""
    H, W = full_shape
    fy, fx = H // net_shape[0], W // net_shape[1]
    if fy != fx or fy * net_shape[0] != H or fx * net_shape[1] != W:
        small = np.zeros(net_shape, bool)
        small[box] = m_box
        return _one_surface(
            cv2.resize(small.astype(np.uint8), (W, H), interpolation=cv2.INTER_NEAREST).astype(bool), frame
        )
    f = fy
    rows, cols = slice(box[0].start * f, box[0].stop * f), slice(box[1].start * f, box[1].stop * f)
    big = np.repeat(np.repeat(m_box, f, axis=0), f, axis=1)  # INTER_NEAREST at an exact factor: pixel (v // f, u // f)
    full = np.zeros((H, W), bool)
    full[rows, cols] = _near_median_depth(big, frame.depth_m[rows, cols])
    return full


def _one_surface(mask: np.ndarray, frame: CameraFrame) -> np.ndarray:
    """The mask without pixels far in depth from its median: where a mask found at half resolution and scaled up
    spills past an object's silhouette onto the wall or floor behind (meters away), those pixels would drag the
    object's 3D points with them."""
    return _near_median_depth(mask, frame.depth_m)


def _near_median_depth(mask: np.ndarray, depth_m: np.ndarray) -> np.ndarray:
    """The mask's pixels within DEPTH_SPREAD_M of its median finite depth (`depth_m` the same shape as the
    mask); the mask itself when none has a depth."""
    d = depth_m[mask]
    ok = np.isfinite(d)
    if not ok.any():
        return mask
    med = float(np.median(d[ok]))
    keep = np.zeros_like(mask)
    keep[mask] = ok & (np.abs(d - med) <= DEPTH_SPREAD_M)
    return keep


def _depth_edges(depth_m: np.ndarray) -> np.ndarray:
    """Pixels next to a depth jump: where one object ends in front of another of the same category."""
    d = np.nan_to_num(depth_m.astype(np.float32), nan=0.0, posinf=10.0)
    gx = np.abs(np.diff(d, axis=1, append=d[:, -1:]))
    gy = np.abs(np.diff(d, axis=0, append=d[-1:, :]))
    jump = np.maximum(gx, gy)
    return jump > np.maximum(DEPTH_EDGE_M, 0.02 * d)


def _grow_into(comp: np.ndarray, region: np.ndarray, iterations: int = 4) -> np.ndarray:
    """Give the region's pixels cut away as boundary back to the neighbouring component (a few pixels deep).

    Worked inside the bounding box of the region and of every labelled pixel: only region pixels change, and only
    to a label within one pixel, so nothing outside that box can matter (past its edge every label is 0, and
    cv2.dilate ignores what lies beyond an image's border)."""
    comp = comp.astype(np.int32)
    occupied = region | (comp > 0)
    rows, cols = np.flatnonzero(occupied.any(1)), np.flatnonzero(occupied.any(0))
    if not len(rows):
        return comp
    box = (slice(rows[0], rows[-1] + 1), slice(cols[0], cols[-1] + 1))
    c, r = comp[box], region[box]
    kernel = np.ones((3, 3), np.uint8)
    for _ in range(iterations):
        free = r & (c == 0)
        if not free.any():
            break
        grown = cv2.dilate(c.astype(np.float32), kernel).astype(np.int32)
        c = np.where(free & (grown > 0), grown, c)
    comp[box] = c
    return comp


def _footprint_xy(mask: np.ndarray, frame: CameraFrame) -> tuple[np.ndarray, float]:
    """Median xy of a mask's world points and the radius of its seen footprint (half its wider xy extent between
    the 5th and 95th percentiles), in m."""
    vs, us = mask_pixels(mask)
    pts = frame.backproject(us.astype(float), vs.astype(float), frame.depth_m[vs, us])[:, :2]
    pts = pts[np.isfinite(pts).all(1)]
    if not len(pts):
        return np.full(2, np.nan), 0.0
    lo, hi = percentiles(pts, (5, 95))
    return np.median(pts, axis=0), float(0.5 * (hi - lo).max())


def _centroid_xy(mask: np.ndarray, frame: CameraFrame) -> np.ndarray:
    vs, us = mask_pixels(mask)
    pts = frame.backproject(us.astype(float), vs.astype(float), frame.depth_m[vs, us])
    return np.median(pts[:, :2], axis=0)
