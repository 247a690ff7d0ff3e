"""Adaptive prompt self-consistency: try K prompts for one object, keep the one that yields exactly one
confident detection, discard ambiguous ones, and record every candidate and the choice.

The paper's threshold rule: the segmenter reports detections at its model's default threshold (SAM3: 0.3, see
sam3_segmenter.MODEL_SCORE_THRESHOLD). With alternative prompts (the adaptive configuration) the adaptive rule
supersedes that threshold: a prompt counts only when it gives exactly one detection (two reported instances make
it ambiguous) and that detection is confident (>= CONFIDENT); the most confident such prompt is kept. With the
label alone (fair, bddl) its single detection is kept at the segmenter's own threshold."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from .detection import Detection
from .frame import CameraFrame
from .lifting import merge_duplicates
from .segmenter import Segmenter

CONFIDENT = 0.5
TRACK_RADIUS_M = 0.08  # how far an object may be from where it was last resolved to be taken as the same one


@dataclass(frozen=True)
class PromptCandidate:
    prompt: str
    n_detections: int
    best_score: float
    verdict: str  # chosen | single | ambiguous | none | weak | tracked


@dataclass(frozen=True)
class PromptSelection:
    label: str
    detection: Detection | None  # relabelled with `label`
    candidates: tuple[PromptCandidate, ...] = field(default_factory=tuple)
    # the confident detections of every prompt that found several (their own prompts kept): what another view's
    # choice is checked against (resolver.several_elsewhere)
    ambiguous: tuple[Detection, ...] = field(default_factory=tuple)

    @property
    def chosen_prompt(self) -> str | None:
        return self.detection.prompt if self.detection else None

    def to_dict(self) -> dict:
        return {"label": self.label, "chosen": self.chosen_prompt, "candidates": [c.__dict__ for c in self.candidates]}


def select_prompt(
    segmenter: Segmenter,
    frame: CameraFrame,
    label: str,
    variants: list[str],
    confident: float | None = None,
    keep_apart: frozenset[str] = frozenset(),
    seen_at_m: np.ndarray | None = None,
) -> PromptSelection:
    """Segment with the label and its variants in one call (split masks of one object merged first, except for
    prompts in `keep_apart`); keep the best single confident detection. `confident` None: the threshold rule
    above (CONFIDENT with alternatives, the segmenter's own threshold for the label alone).

    `seen_at_m`: where this label's object was last resolved (world frame, m). When every prompt is ambiguous,
    the confident detection nearest that point (within TRACK_RADIUS_M) is kept, verdict "tracked": in the middle
    of a task the scene holds new look-alikes (an opened drawer's inside looks like a bowl to a small network)
    while the object itself has not moved far since it was last seen."""
    prompts = list(dict.fromkeys([label, *variants]))
    if confident is None:
        confident = detection_threshold(segmenter, adaptive=len(prompts) > 1)
    dets = merge_duplicates(segmenter.segment(frame, prompts), keep_apart=keep_apart)
    by_prompt: dict[str, list[Detection]] = {p: [] for p in prompts}
    for d in dets:
        by_prompt.setdefault(d.prompt, []).append(d)
    candidates, singles, several = [], [], []
    for p in prompts:
        ds = by_prompt[p]
        best = max((d.score for d in ds), default=0.0)
        if not ds:
            verdict = "none"
        elif len(ds) > 1:
            verdict = "ambiguous"
            several += [d for d in ds if d.score >= confident]
        elif best < confident:
            verdict = "weak"
        else:
            verdict = "single"
            singles.append(ds[0])
        candidates.append(PromptCandidate(p, len(ds), round(best, 4), verdict))
    if not singles and seen_at_m is not None:
        near = _nearest([d for d in dets if d.score >= confident], frame, np.asarray(seen_at_m, float), TRACK_RADIUS_M)
        if near is not None:
            candidates = [
                PromptCandidate(
                    c.prompt, c.n_detections, c.best_score, "tracked" if c.prompt == near.prompt else c.verdict
                )
                for c in candidates
            ]
            return PromptSelection(label, near.with_label(label), tuple(candidates), tuple(several))
    if not singles:
        return PromptSelection(label, None, tuple(candidates), tuple(several))
    chosen = max(singles, key=lambda d: d.score)
    candidates = [
        PromptCandidate(c.prompt, c.n_detections, c.best_score, "chosen" if c.prompt == chosen.prompt else c.verdict)
        for c in candidates
    ]
    return PromptSelection(label, chosen.with_label(label), tuple(candidates), tuple(several))


def detection_threshold(segmenter: Segmenter, adaptive: bool) -> float:
    """The score a prompt's single detection needs to be kept: CONFIDENT when the adaptive rule chooses among
    alternative prompts; otherwise the segmenter's own reporting threshold (SAM3: its model's default), or
    CONFIDENT for segmenters without one."""
    own = getattr(segmenter, "score_threshold", None)
    return CONFIDENT if adaptive or own is None else float(own)


def _nearest(dets: list[Detection], frame: CameraFrame, point_m: np.ndarray, radius_m: float) -> Detection | None:
    """The detection whose mask's median 3D point lies nearest `point_m`, if within `radius_m`."""
    best, best_d = None, radius_m
    for d in dets:
        vs, us = np.nonzero(d.mask)
        z = frame.depth_m[vs, us]
        ok = np.isfinite(z) & (z > 0)
        if not ok.any():
            continue
        c = np.median(frame.backproject(us[ok].astype(float), vs[ok].astype(float), z[ok]), axis=0)
        dist = float(np.linalg.norm(c - point_m))
        if dist < best_d:
            best, best_d = d, dist
    return best
