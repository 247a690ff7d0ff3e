"""Perception benchmark of the learned (camera-only) segmenter on held-out scenes: per-category mask IoU,
instance precision and recall, keypoint error against ground truth, and inference time per 640x480 frame.

Held-out scenes use seeds from BENCH_SEED0 (940,000 + k; LIBERO 918,000 + k), disjoint from the training seeds
(1,000,000 + k), from the development scenes tests use, and from every task benchmark's seeds (0..999). Ground truth
(renderer ids, object poses) is read here for scoring only; the segmenter sees frames without ids."""

from __future__ import annotations

import time
from collections.abc import Callable
from pathlib import Path

import numpy as np

from ..perception.detection import Detection
from ..perception.frame import CameraFrame
from ..perception.keypoint import LabelNotFound
from ..perception.learned.categories import CATEGORIES
from ..perception.learned.dataset import BENCH_SEED0, geom_tables, random_world, render_labelled
from ..perception.learned.segmenter import LearnedSegmenter
from ..perception.lifting import keypoint_from_points, masked_points
from ..perception.privileged import PrivilegedResolver
from ..perception.resolver import PerceptionResolver, fused_evidence
from ..perception.sim_segmenter import SimSegmenter
from ..sim.cameras import label_table
from .report import footer, pct

MIN_GT_AREA_PX = 50  # ground-truth instances smaller than this (at 640x480) are not counted as missed
MATCH_IOU = 0.5
CAMERAS = ("agentview", "side")
SUITE_CAMERAS = {
    "builtin": CAMERAS,
    "random": CAMERAS,
    "libero": ("agentview", "frontview"),
    "capbench": ("agentview", "sideview"),
}  # as the suites use
LIBERO_TASK_STRIDE = 5  # every 5th LIBERO-PRO task: 2 of the 10 tasks of each of the 6 cells


# seeds one round of held-out scenes spans
ROUND_STRIDE = {"builtin": 100, "random": 200, "libero": 600, "capbench": 35}


CAPBENCH_NOTE = (
    "; capbench = each of the seven CaP-Bench tasks reset by the env's own samplers from the seed (1,700,020 and "
    "up train), lighting and arm pose jittered, cameras agentview and sideview; the pot, hammer and Wipe's dirt "
    "have categories of their own since 2026-11-27 (weights trained before that never predict them)"
)


def _scene_worlds(suite: str, n_seeds: int, round_: int = 0) -> list[tuple[str, int, Callable]]:
    """(scene name, seed, world factory) of a suite's held-out scenes. LIBERO: LIBERO's placement samplers from
    seeds LIBERO_BENCH_SEED0 + 10 * task + k (never an init state; training seeds are 1,500,000 and up).
    `round_` > 0 moves every range by that many ROUND_STRIDE blocks: scenes nobody has looked at, once the
    round-0 scenes have guided a change."""
    per_task = {"libero": 10, "capbench": 5}  # consecutive seeds of one task in those sources
    if n_seeds > per_task.get(suite, ROUND_STRIDE[suite] // (7 if suite == "random" else 1)):
        raise ValueError(f"{n_seeds} scenes per task overrun one round of {suite} held-out seeds")
    shift = round_ * ROUND_STRIDE[suite]
    if suite == "libero":
        from ..perception.learned.libero_data import LIBERO_BENCH_SEED0, LiberoScenes, libero_tasks

        scenes = LiberoScenes()
        tasks = libero_tasks()
        return [
            (t.name, LIBERO_BENCH_SEED0 + shift + 10 * i + k, lambda s, t=t: scenes.scene(s, t))
            for i, t in enumerate(tasks)
            if i % LIBERO_TASK_STRIDE == 0
            for k in range(n_seeds)
        ]
    if suite == "capbench":  # the envs' own samplers from CAPBENCH_BENCH_SEED0 + 5 * task + k (training: 1,700,020+)
        from ..perception.learned.capbench_data import CAPBENCH_BENCH_SEED0, SCENES_PER_TASK, TASKS, CapbenchScenes

        cap = CapbenchScenes()
        return [
            (t, CAPBENCH_BENCH_SEED0 + shift + SCENES_PER_TASK * i + k, lambda s, t=t: cap.scene(s, t))
            for i, t in enumerate(TASKS)
            for k in range(n_seeds)
        ]
    if suite == "builtin":
        from ..sim.tasks import BUILTIN

        return [
            (name, BENCH_SEED0 + shift + k, lambda s, t=task: t.make_world(s))
            for name, task in BUILTIN.items()
            for k in range(n_seeds)
        ]
    if suite == "random":
        return [("random", BENCH_SEED0 + 5000 + shift + k, lambda s: random_world(s)[0]) for k in range(n_seeds * 7)]
    raise ValueError(f"no perception bench scenes for suite {suite!r}; have: builtin, random, libero, capbench")


def _match(gt: dict[int, np.ndarray], pred: list[np.ndarray]) -> int:
    """Greedy one-to-one matches at IoU >= MATCH_IOU (the best pairs first)."""
    pairs = []
    for g, gm in gt.items():
        for p, pm in enumerate(pred):
            inter = int((gm & pm).sum())
            if inter:
                iou = inter / int((gm | pm).sum())
                if iou >= MATCH_IOU:
                    pairs.append((iou, g, p))
    used_g, used_p = set(), set()
    for _, g, p in sorted(pairs, reverse=True):
        if g not in used_g and p not in used_p:
            used_g.add(g)
            used_p.add(p)
    return len(used_g)


def evaluate_world(world, seg: LearnedSegmenter, acc: dict, suite: str = "builtin") -> None:
    """Add one world's frames and keypoints to the accumulators in `acc`."""
    cameras = SUITE_CAMERAS[suite]
    if suite == "libero":
        from ..perception.learned.libero_data import libero_geom_tables

        tables = libero_geom_tables(world)
    elif suite == "capbench":
        from ..perception.learned.capbench_data import capbench_geom_tables

        tables = capbench_geom_tables(world)
    else:
        tables = geom_tables(world)
    true_views: list[tuple[CameraFrame, np.ndarray]] = []
    for cam in cameras:
        lf = render_labelled(world, cam, tables)
        frame = CameraFrame(cam, lf.rgb, lf.depth_m, lf.K, lf.T_world_camera)  # no ids, no labels
        true_views.append((frame, lf.instance))
        seg._cache.clear()
        t0, c0 = time.perf_counter(), time.process_time()
        insts = seg.instances(frame)
        acc["ms"].append(1000 * (time.perf_counter() - t0))
        acc["cpu_ms"].append(1000 * (time.process_time() - c0))
        pred_cat = np.zeros(lf.category.shape, np.int32)
        for inst in insts:
            pred_cat[inst.mask] = inst.category
        for c, cat in enumerate(CATEGORIES):
            if not cat.thing:
                continue
            g, p = lf.category == c, pred_cat == c
            acc["inter"][c] += int((g & p).sum())
            acc["union"][c] += int((g | p).sum())
        gt = {
            int(i): lf.instance == i
            for i in np.unique(lf.instance)
            if i
            and (lf.instance == i).sum() >= MIN_GT_AREA_PX
            and CATEGORIES[int(np.bincount(lf.category[lf.instance == i]).argmax())].thing
        }
        matched = _match(gt, [i.mask for i in insts])
        acc["gt"] += len(gt)
        acc["pred"] += len(insts)
        acc["matched"] += matched
    truth = PrivilegedResolver(world)
    learned = PerceptionResolver(world, seg, cameras=cameras)
    oracle = PerceptionResolver(world, SimSegmenter(world.scene.catalog()), cameras=cameras)
    instance_of = {label: i for i, label in label_table(world)[0].items()}
    targets = [label for label, o in world.scene.objects.items() if o.spec.kind != "ball"] + list(world.scene.parts)
    for label in targets:
        gt_pos = truth.resolve(label).position_m
        ref = true_mask_keypoint(label, instance_of[label], true_views)
        for name, res in (("learned", learned), ("sim", oracle)):
            acc[f"kp_{name}_n"] += 1
            try:
                kp = res.resolve(label)
            except LabelNotFound:
                acc[f"kp_{name}_missing"].append(label)
                continue
            acc[f"kp_{name}"].append(float(np.linalg.norm(kp.position_m - gt_pos)))
            if ref is not None:
                acc[f"kpm_{name}"].append(float(np.linalg.norm(kp.position_m - ref)))


def true_mask_keypoint(label: str, instance: int, views: list[tuple[CameraFrame, np.ndarray]]) -> np.ndarray | None:
    """The keypoint (world frame, m) the trial resolver's lifting gives from the renderer's TRUE instance mask of
    `label` in each view: what a perfect segmenter would yield. The simulator's AABB centre is no fair target for
    a camera: a closed drawer's box or a cabinet's back is never visible (with true masks it sits 4-9 cm from the
    visible-surface estimate). None when no view sees the object."""
    evidence = []
    for frame, inst in views:
        det = Detection(label, label, inst == instance, 1.0, frame.camera, privileged=True)
        ev = masked_points(det, frame)
        if ev is not None:
            evidence.append(ev)
    evidence = fused_evidence(evidence)
    return keypoint_from_points(label, evidence, "true masks").position_m if evidence else None


def run(
    suites: tuple[str, ...] = ("builtin", "random", "libero"),
    n_seeds: int = 3,
    progress=print,
    weights: str | None = None,
    round_: int = 0,
) -> dict:
    """Per suite: instance precision/recall, per-category IoU, keypoint errors (learned and the sim oracle) and
    inference time; `weights` None = the shipped ones; `round_` picks the held-out seed round (_scene_worlds)."""
    seg = LearnedSegmenter(weights)
    out = {}
    for suite in suites:
        acc: dict = {
            "ms": [],
            "cpu_ms": [],
            "inter": np.zeros(len(CATEGORIES)),
            "union": np.zeros(len(CATEGORIES)),
            "gt": 0,
            "pred": 0,
            "matched": 0,
            "kp_learned": [],
            "kp_sim": [],
            "kpm_learned": [],
            "kpm_sim": [],
            "kp_learned_n": 0,
            "kp_sim_n": 0,
            "kp_learned_missing": [],
            "kp_sim_missing": [],
        }
        scenes = _scene_worlds(suite, n_seeds, round_)
        for i, (name, seed, make) in enumerate(scenes):
            world = make(seed)
            try:
                evaluate_world(world, seg, acc, suite)
            finally:
                world.close()
            progress(f"{suite} {i + 1}/{len(scenes)} {name} seed {seed}: recall {acc['matched']}/{acc['gt']}")
        ms = acc["ms"][1:] or acc["ms"]  # the first frame also loads the network
        cpu_ms = acc["cpu_ms"][1:] or acc["cpu_ms"]
        out[suite] = {
            "scenes": len(scenes),
            "frames": len(acc["ms"]),
            "instance_precision": acc["matched"] / max(acc["pred"], 1),
            "instance_recall": acc["matched"] / max(acc["gt"], 1),
            "gt_instances": acc["gt"],
            "pred_instances": acc["pred"],
            "category_iou": {
                CATEGORIES[c].name: acc["inter"][c] / acc["union"][c]
                for c in range(len(CATEGORIES))
                if acc["union"][c] > 0
            },
            "inference_ms_median": float(np.median(ms)),
            "inference_ms_p95": float(np.percentile(ms, 95)),
            "inference_cpu_ms_median": float(np.median(cpu_ms)),
            **{
                f"kp_{n}_{q}": (float(np.percentile(acc[f"kp_{n}"], p)) if acc[f"kp_{n}"] else None)
                for n in ("learned", "sim")
                for q, p in (("median_m", 50), ("p95_m", 95))
            },
            **{
                f"kpm_{n}_{q}": (float(np.percentile(acc[f"kpm_{n}"], p)) if acc[f"kpm_{n}"] else None)
                for n in ("learned", "sim")
                for q, p in (("median_m", 50), ("p95_m", 95))
            },
            "kp_learned_resolved": f"{len(acc['kp_learned'])}/{acc['kp_learned_n']}",
            "kp_sim_resolved": f"{len(acc['kp_sim'])}/{acc['kp_sim_n']}",
            "kp_learned_missing": sorted(set(acc["kp_learned_missing"])),
            "scene_seeds": f"{scenes[0][1]}..{scenes[-1][1]}" if scenes else "",
        }
    return out


def _cm(x: float | None) -> str:
    return "-" if x is None else f"{100 * x:.2f} cm"


def section(r: dict, command: str, weights: str | None = None) -> str:
    from ..perception.learned.segmenter import default_weights

    w = Path(weights) if weights else default_weights()
    weights_note = (
        f"weights {w.name}, {w.stat().st_size / 1e6:.1f} MB, trained on builtin and LIBERO renders: see MODEL_CARD.md"
    )
    lines = [
        "| scenes | frames | instance precision | instance recall | keypoint error median | keypoint error p95 "
        "| labels resolved | to the AABB centre: learned median / p95 | to the AABB centre: sim oracle median / p95 "
        "| inference per 640x480 frame: wall ms median / p95, CPU ms median |",
        "|---|---|---|---|---|---|---|---|---|---|",
    ]
    for suite, s in r.items():
        lines.append(
            f"| {suite} | {s['frames']} | {pct(s['instance_precision'])} | {pct(s['instance_recall'])} "
            f"| {_cm(s['kpm_learned_median_m'])} | {_cm(s['kpm_learned_p95_m'])} | {s['kp_learned_resolved']} "
            f"| {_cm(s['kp_learned_median_m'])} / {_cm(s['kp_learned_p95_m'])} "
            f"| {_cm(s['kp_sim_median_m'])} / {_cm(s['kp_sim_p95_m'])} "
            f"| {s['inference_ms_median']:.0f} / {s['inference_ms_p95']:.0f}, {s['inference_cpu_ms_median']:.0f} |"
        )
    cats = sorted({c for s in r.values() for c in s["category_iou"]})
    lines += ["", "Per-category mask IoU:", "", "| category | " + " | ".join(r) + " |", "|---" * (len(r) + 1) + "|"]
    for c in cats:
        lines.append(
            f"| {c} | "
            + " | ".join(pct(s["category_iou"][c]) if c in s["category_iou"] else "-" for s in r.values())
            + " |"
        )
    seeds = "; ".join(f"{k}: seeds {s['scene_seeds']}" for k, s in r.items())
    protocol = (
        "segmenter `learned` (camera-only, NOT privileged: RGB-D frames without ids; "
        f"{weights_note}); held-out scenes ({seeds}; training seeds are 1,000,000 and up; builtin = every "
        "builtin task's start scene, random = random object sets, arm poses and lighting, libero = every "
        f"{LIBERO_TASK_STRIDE}th LIBERO-PRO task (2 per cell) placed by LIBERO's own samplers from the seed, lighting "
        f"and arm pose jittered, never a LIBERO-PRO init state{CAPBENCH_NOTE if 'capbench' in r else ''}); cameras "
        "agentview and side (libero: agentview and frontview) at 640x480; "
        f"instances matched one-to-one at mask IoU >= {MATCH_IOU}, ground-truth instances under "
        f"{MIN_GT_AREA_PX} px not counted; keypoints through the trial resolver (adaptive prompts, both views "
        "fused) for every object's own label (beads excluded: five identical ones) and every labelled part; keypoint "
        "error = distance to the keypoint the same lifting gives from the renderer's TRUE instance masks in the same "
        "frames (what a perfect segmenter yields: the segmenter's own error); the distance to the simulator's AABB "
        "centre is shown too, for the learned segmenter and for the same resolver with the PRIVILEGED `sim` oracle "
        "masks (it adds the lifting's error on hidden volumes: a closed drawer's box, a cabinet's back); "
        "inference = network (one torch thread) + instance extraction, "
        "wall time on the shared machine as it was loaded during the run, and process CPU time"
    )
    return "\n".join(lines) + "\n\n" + footer(command, protocol)
