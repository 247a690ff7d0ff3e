"""PerceptionResolver: label -> keypoint through cameras, a segmenter, adaptive prompts and depth lifting.

Late binding: frames are re-captured whenever simulated time has moved since the last capture, so every node
resolves its labels from what the cameras see at the moment it runs. `refresh()` forces a new capture (the
executor's tier-2 recovery calls it after retracting).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any

import numpy as np

from .adaptive import PromptSelection, select_prompt
from .detection import Detection
from .frame import CameraFrame
from .keypoint import Keypoint, LabelNotFound
from .lifting import PointEvidence, keypoint_from_points, masked_points, wrist_self_occlusion
from .segmenter import Segmenter
from .variants import prompt_variants

FUSE_AGREEMENT_M = 0.05
FUSE_OVERLAP = 0.5  # ...or when their xy point boxes overlap by more than this share of the smaller box
# a second object seen in one view makes a label another view singled out ambiguous (several_elsewhere) when that
# view is sure of it and it has about the kept one's size
SECOND_SURE = 0.9
SECOND_SIZE_RATIO = 2.0


class PerceptionResolver:
    def __init__(
        self,
        world,
        segmenter: Segmenter,
        cameras: Sequence[str] = ("agentview", "side"),
        adaptive: bool = True,
        k_variants: int = 3,
        variants: Callable[[str], list[str]] | None = None,
        size: tuple[int, int] = (640, 480),
    ):
        self.world = world
        self.segmenter = segmenter
        self.cameras = tuple(cameras)
        self.adaptive = adaptive
        self.k_variants = k_variants
        self.variants = variants or (lambda label: prompt_variants(label, k_variants))
        self.size = size
        self.privileged = bool(segmenter.privileged)
        self.source = segmenter.name + (" (privileged masks)" if self.privileged else "")
        self.frames: dict[str, CameraFrame] = {}
        self._captured_at: float | None = None
        self._first_capture_at: float | None = None  # sim time of the first look: the scene before the robot acts
        self.refreshes = 0
        self.groundings: list[dict] = []  # every resolution: label, prompt candidates, choice, keypoint
        # called with each grounding record as it is made, while its frames and detections are still the
        # resolver's latest (a trace sink stores it and its images while the trial runs)
        self.grounding_listeners: list[Callable[[dict], None]] = []
        self.detections: dict[str, dict[str, Detection]] = {}  # camera -> label -> latest chosen detection
        self._seen_at: dict[str, np.ndarray] = {}  # label -> where it was last resolved (world, m)

    def use_variants(self, table: dict[str, list[str]]) -> None:
        """Alternative prompts per label from elsewhere (an LLM's prompt-synthesis call); labels it has none for
        keep the offline synonym table."""
        fallback = self.variants
        self.variants = lambda label: table.get(label) or fallback(label)

    def refresh(self) -> None:
        self.refreshes += 1
        self._capture()

    def _capture(self) -> None:
        w, h = self.size
        frames = {}
        for cam in self.cameras:
            frame = self.world.render(cam, w, h)
            perturb = getattr(self.segmenter, "perturb_frame", None)
            frames[cam] = perturb(frame) if perturb else frame
        self.frames = frames
        self._captured_at = self.world.sim_time_s
        if self._first_capture_at is None:
            self._first_capture_at = self._captured_at

    def _ensure_fresh(self) -> None:
        if self._captured_at is None or self.world.sim_time_s != self._captured_at:
            self._capture()

    def inventory(self) -> list[str]:
        """Names of the things in the current frames ("black bowl (2)" for two), for segmenters that can list them
        (`names_in`: the sim oracle from its privileged object ids, the learned segmenter from its own instances);
        empty for the others."""
        names_in = getattr(self.segmenter, "names_in", None)
        if names_in is None:
            return []
        self._ensure_fresh()
        count: dict[str, int] = {}
        for frame in self.frames.values():
            names = names_in(frame)
            for n in set(names):
                count[n] = max(count.get(n, 0), names.count(n))
        return [n if k == 1 else f"{n} ({k})" for n, k in sorted(count.items())]

    def resolve(self, label: str) -> Keypoint:
        self._ensure_fresh()
        variants = self.variants(label) if self.adaptive else []
        evidence: list[PointEvidence] = []
        record: dict[str, Any] = {"label": label, "t_sim_s": self._captured_at, "cameras": {}}
        seen_at = self._seen_at.get(label)
        selections = {}
        for cam, frame in self.frames.items():
            sel = selections[cam] = select_prompt(self.segmenter, frame, label, variants, seen_at_m=seen_at)
            record["cameras"][cam] = sel.to_dict()
            if sel.detection is None:
                continue
            self.detections.setdefault(cam, {})[label] = sel.detection
            exclude = wrist_self_occlusion(frame.shape) if "wrist" in cam else None
            ev = masked_points(sel.detection, frame, exclude)
            if ev is not None:
                evidence.append(ev)
        evidence = fused_evidence(evidence)
        # on the scene as it was before the robot acted (the planner's look) a view that sees several of what another
        # view kept makes the label ambiguous: one view may simply not see the second bowl. Later looks track the
        # object already chosen (select_prompt's seen_at_m) or keep the single detection, so look-alikes appearing
        # mid-task (an opened drawer's inside) do not undo a plan.
        before_acting = self._captured_at == self._first_capture_at and seen_at is None
        several = several_elsewhere(selections, self.frames, evidence) if evidence and before_acting else 0
        if several > 1:
            record["keypoint"] = None
            record["several"] = several
            self._add_grounding(record)
            raise LabelNotFound(label, f"several match: {several} (one view saw one, another saw {several})")
        if not evidence:
            tried = ", ".join([label, *variants])
            record["keypoint"] = None
            self._add_grounding(record)
            raise LabelNotFound(label, f"no single confident detection in {', '.join(self.cameras)} (prompts: {tried})")
        kp = keypoint_from_points(label, evidence, self.source)
        self._seen_at[label] = kp.position_m
        record["keypoint"] = kp.to_dict()
        self._add_grounding(record)
        return kp

    def _add_grounding(self, record: dict) -> None:
        self.groundings.append(record)
        for listener in list(self.grounding_listeners):
            listener(record)


def several_elsewhere(
    selections: dict[str, PromptSelection], frames: dict[str, CameraFrame], kept: list[PointEvidence]
) -> int:
    """How many distinct objects (in 3D) some view holds for a prompt another view kept as its single detection:
    the kept object (`kept`, the fused evidence) plus every other one that view is sure of (score >=
    SECOND_SURE) and that has about the kept object's size (SECOND_SIZE_RATIO); 0 when there is none.

    A detection is the kept object when `_same_object` says so against any kept view (a plate one view sees whole
    and another in two pieces either side of a bottle in front of it). The bars keep a segmenter's slips from
    refusing a plannable task: a box of cream cheese one view takes for a second bowl at 0.75, a burner seen as a
    second stove a third of its size. Only instances of the kind count (`_an_instance`), and when the kept answer is
    a parent standing in for a part, nothing was singled out to compare with."""
    if any(e.detection.detail.get("stand_in_for_part") for e in kept):
        return 0
    prompts = {s.chosen_prompt for s in selections.values() if s.detection is not None}
    size = max(_xy_size(e) for e in kept)
    most = 0
    for cam, sel in selections.items():
        frame = frames[cam]
        exclude = wrist_self_occlusion(frame.shape) if "wrist" in cam else None
        for prompt in prompts:
            others: list[PointEvidence] = []
            for d in sel.ambiguous:
                if d.prompt != prompt or d.score < SECOND_SURE or not _an_instance(d):
                    continue
                e = masked_points(d, frame, exclude)
                if e is None or any(_same_object(e, o) for o in [*kept, *others]):
                    continue
                if max(_xy_size(e), size) <= SECOND_SIZE_RATIO * min(_xy_size(e), size):
                    others.append(e)
            most = max(most, 1 + len(others) if others else 0)
    return most


def _an_instance(d: Detection) -> bool:
    """Whether a detection of an ambiguous prompt counts as one more of the kind: not a parent standing in for a
    part it could not see, and not one of several a relational label ("the bowl on the stove") left undecided in a
    view that saw none of its anchors (the view that saw them decided)."""
    undecided = "relation_anchors" in d.detail and "relation_holds" not in d.detail
    return not (d.detail.get("stand_in_for_part") or undecided)


def _xy_size(e: PointEvidence) -> float:
    """The longer side of the view's xy point box (5th-95th percentile), m."""
    lo, hi = np.percentile(e.points_world[:, :2], 5, axis=0), np.percentile(e.points_world[:, :2], 95, axis=0)
    return float(max(hi - lo))


def _same_object(a: PointEvidence, b: PointEvidence) -> bool:
    """The views' rule for one thing (fused_evidence): medians within FUSE_AGREEMENT_M in xy or xy boxes
    overlapping by FUSE_OVERLAP (of the smaller box: a piece inside the whole), and heights within FUSE_AGREEMENT_M
    or half the taller visible height."""
    ca, cb = np.median(a.points_world, axis=0), np.median(b.points_world, axis=0)
    same_xy = np.linalg.norm(ca[:2] - cb[:2]) < FUSE_AGREEMENT_M or _xy_overlap(a, b) > FUSE_OVERLAP
    tall = max(float(np.percentile(e.points_world[:, 2], 98) - np.percentile(e.points_world[:, 2], 2)) for e in (a, b))
    return bool(same_xy and abs(ca[2] - cb[2]) < max(FUSE_AGREEMENT_M, 0.5 * tall))


def fused_evidence(evidence: list[PointEvidence]) -> list[PointEvidence]:
    """Fuse views only when they saw the same thing; otherwise trust the most confident view. The same thing: the
    medians of the views' points within FUSE_AGREEMENT_M in xy (or their xy boxes overlapping, FUSE_OVERLAP: one
    side of a bowl seen from the front) and, in height, within FUSE_AGREEMENT_M or half
    the most confident view's visible height (stacked drawers' handles share xy and differ in height by less than
    a handle's spacing; a bottle seen from above and from the side differs by more than 5 cm and is one thing).
    For a relational label ("the bowl on the stove") a view whose pick was seen to stand in the relation is
    trusted before one whose pick was seen not to (one view may hold only the wrong bowl), whatever the scores.
    A view that did not see a named part and answered with its parent ("drawer handle" -> the cabinet) gives way
    to any view that saw the part itself."""
    direct = [e for e in evidence if not e.detection.detail.get("stand_in_for_part")]
    evidence = direct or evidence
    if len(evidence) < 2:
        return evidence
    best = max(evidence, key=lambda e: (_relation_rank(e), e.detection.score))
    centre = np.median(best.points_world, axis=0)
    z = best.points_world[:, 2]
    z_tol = max(FUSE_AGREEMENT_M, 0.5 * float(np.percentile(z, 98) - np.percentile(z, 2)))
    out = []
    for e in evidence:
        c = np.median(e.points_world, axis=0)
        same_xy = np.linalg.norm(c[:2] - centre[:2]) < FUSE_AGREEMENT_M or _xy_overlap(e, best) > FUSE_OVERLAP
        if same_xy and abs(c[2] - centre[2]) < z_tol:
            out.append(e)
    return out


def _xy_overlap(a: PointEvidence, b: PointEvidence) -> float:
    """Area of the intersection of the two views' xy point boxes (5th-95th percentile) over the smaller box's. A
    view that sees one side of a wide object (a bowl's near half from the front) has its median 5-6 cm from the
    other view's, yet its box lies inside the other's."""
    boxes = [
        (np.percentile(e.points_world[:, :2], 5, axis=0), np.percentile(e.points_world[:, :2], 95, axis=0))
        for e in (a, b)
    ]
    (la, ha), (lb, hb) = boxes
    inter = float(np.clip(np.minimum(ha, hb) - np.maximum(la, lb), 0.0, None).prod())
    smaller = min(float((ha - la).prod()), float((hb - lb).prod()))
    return inter / max(smaller, 1e-9)


def _relation_rank(e: PointEvidence) -> int:
    """2: the view saw its pick stand in the label's relation; 0: saw it not; 1: no relation, or not checked."""
    holds = e.detection.detail.get("relation_holds")
    return 1 if holds is None else 2 if holds else 0
