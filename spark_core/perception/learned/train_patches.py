"""Train the patch classifier (patch_classifier.py) on a rendered dataset's crops (dataset.py).

Every object instance of a crop is a sample, labelled with its category (parts as "other"); so is, once per crop,
a random blob of table, floor or robot (what a shadow the per-pixel network took for an item looks like), as
"other".
Patches are cut as the segmenter cuts them at run time, with the differences between a true mask and a predicted
one simulated: the window jittered in place and scale, the mask eroded or dilated, made blocky as a half-resolution
mask scaled up, or cut to a part of the object; brightness and white balance jittered, flipped left-right.
"""

from __future__ import annotations

import json
import time
from collections.abc import Callable
from dataclasses import asdict, dataclass
from pathlib import Path

import cv2
import numpy as np
import torch
from torch.nn import functional as F

from .categories import CATEGORIES
from .dataset import load_shards
from .patch_classifier import CLASS_CATEGORY, CLASSES, OTHER, PatchNet, patch, save, square_box

MIN_AREA_PX = 40  # instances smaller than this (camera pixels) are not samples


@dataclass(frozen=True)
class PatchTrainConfig:
    data_dirs: tuple[str, ...]
    out: str
    minutes: float = 12.0
    steps: int = 100_000
    batch: int = 96
    lr: float = 2e-3
    seed: int = 0
    threads: int = 1
    val_every: int = 10  # scenes whose seed is -1 mod this are validation (LIBERO: one scene of every task)
    other_fraction: float = 0.25  # share of "other" samples in a batch


BLOB = -1  # instance id of a random non-object blob sample


def samples(data: dict[str, np.ndarray]) -> np.ndarray:
    """(N, 3) int array: crop index, instance id, class index (CLASSES) of every instance of at least
    MIN_AREA_PX pixels, and one BLOB ("other") row per crop."""
    to_class = np.full(len(CATEGORIES), -1)
    to_class[CLASS_CATEGORY] = np.arange(len(CLASS_CATEGORY))
    for i, category in enumerate(CATEGORIES):
        if category.thing and to_class[i] < 0:
            to_class[i] = OTHER
    out = []
    for k in range(len(data["instance"])):
        inst, cat = data["instance"][k], data["category"][k]
        ids, counts = np.unique(inst, return_counts=True)
        for i, n in zip(ids.tolist(), counts.tolist()):
            if i == 0 or n < MIN_AREA_PX:
                continue
            c = int(np.bincount(cat[inst == i]).argmax())
            if to_class[c] >= 0:
                out.append((k, i, int(to_class[c])))
        out.append((k, BLOB, OTHER))
    return np.array(out, np.int64).reshape(-1, 3)


def _perturb_mask(m: np.ndarray, rng: np.random.Generator) -> np.ndarray:
    r = rng.random()
    if r < 0.25:  # the segmenter's masks are found at half resolution and scaled up by nearest pixel
        h, w = m.shape
        small = m[::2, ::2].astype(np.uint8)
        m = cv2.resize(small, (small.shape[1] * 2, small.shape[0] * 2), interpolation=cv2.INTER_NEAREST)[:h, :w]
        m = np.pad(m, ((0, h - m.shape[0]), (0, w - m.shape[1]))).astype(bool)
    elif r < 0.45:
        k = np.ones((3, 3), np.uint8)
        op = cv2.erode if rng.random() < 0.5 else cv2.dilate
        grown = op(m.astype(np.uint8), k, iterations=int(rng.integers(1, 3))).astype(bool)
        m = grown if grown.any() else m
    elif r < 0.55:  # only part of the object found (cut at a random line through it)
        vs, us = np.nonzero(m)
        cv_, cu = np.median(vs), np.median(us)
        a = rng.uniform(0, np.pi)
        yy, xx = np.mgrid[: m.shape[0], : m.shape[1]]
        part = m & (((yy - cv_) * np.sin(a) + (xx - cu) * np.cos(a)) > rng.uniform(-5, 5))
        m = part if part.sum() > 0.3 * m.sum() else m
    return m


def _blob(inst: np.ndarray, rng: np.random.Generator) -> np.ndarray:
    """A random ellipse (4-25 px half-axes) centred on a non-object pixel."""
    vs, us = np.nonzero(inst == 0)
    m = np.zeros(inst.shape, np.uint8)
    if not len(vs):
        return m.astype(bool)
    j = int(rng.integers(len(vs)))
    axes = (int(rng.integers(4, 26)), int(rng.integers(4, 26)))
    cv2.ellipse(m, (int(us[j]), int(vs[j])), axes, float(rng.uniform(0, 180)), 0, 360, 1, -1)
    return m.astype(bool) & (inst == 0)


def _sample_patch(data: dict[str, np.ndarray], k: int, i: int, rng: np.random.Generator | None) -> np.ndarray | None:
    rgb, inst = data["rgb"][k], data["instance"][k]
    depth = data["depth_mm"][k].astype(np.float32) / 1000.0
    m = _blob(inst, rng or np.random.default_rng(k)) if i == BLOB else inst == i
    if rng is None:
        return patch(rgb, depth, m)
    m = _perturb_mask(m, rng)
    box = square_box(m)
    if box is None:
        return None
    r0, c0, win, side = box
    scale = rng.uniform(0.85, 1.25)
    new = max(8, int(win * scale))
    r0 += (win - new) // 2 + int(rng.normal(0, 0.08 * side))
    c0 += (win - new) // 2 + int(rng.normal(0, 0.08 * side))
    p = patch(rgb, depth, m, (r0, c0, new))
    if p is None:
        return None
    p[:3] = np.clip(p[:3] * rng.uniform(0.75, 1.25) * rng.uniform(0.92, 1.08, (3, 1, 1)), 0, 1)
    if rng.random() < 0.5:
        p = p[:, :, ::-1].copy()
    return p


def _batch(data, rows: np.ndarray, rng) -> tuple[torch.Tensor, torch.Tensor]:
    xs, ys = [], []
    for k, i, c in rows.tolist():
        p = _sample_patch(data, k, i, rng)
        if p is not None:
            xs.append(p)
            ys.append(c)
    return torch.from_numpy(np.stack(xs)), torch.tensor(ys)


def accuracy(net: PatchNet, data, rows: np.ndarray) -> dict[str, float]:
    """Per-class accuracy (and overall) on un-augmented patches."""
    net.eval()
    hits: dict[int, list[bool]] = {}
    with torch.no_grad():
        for a in range(0, len(rows), 256):
            x, y = _batch(data, rows[a : a + 256], None)
            pred = net(x).argmax(1)
            for t, p in zip(y.tolist(), pred.tolist()):
                hits.setdefault(t, []).append(t == p)
    net.train()
    out = {CLASSES[c]: round(float(np.mean(h)), 3) for c, h in sorted(hits.items())}
    out["all"] = round(float(np.mean([x for h in hits.values() for x in h])), 3) if hits else 0.0
    return out


def train(cfg: PatchTrainConfig, log: Callable[[str], None] = print) -> dict:
    torch.manual_seed(cfg.seed)
    torch.set_num_threads(cfg.threads)
    rng = np.random.default_rng(cfg.seed)
    if not cfg.data_dirs:
        raise ValueError("no dataset directory given")
    train_rows, val_rows, datas = [], [], []
    for d in cfg.data_dirs:
        data = load_shards(Path(d))
        keep = {k: data.pop(k) for k in ("rgb", "depth_mm", "category", "instance", "seeds")}
        del data
        rows = samples(keep)
        is_val = keep["seeds"][rows[:, 0]] % cfg.val_every == cfg.val_every - 1
        datas.append(keep)
        di = len(datas) - 1
        train_rows.append(np.c_[np.full(int((~is_val).sum()), di), rows[~is_val]])
        val_rows.append(np.c_[np.full(int(is_val.sum()), di), rows[is_val]])
    tr, va = np.concatenate(train_rows), np.concatenate(val_rows)
    offsets = np.cumsum([0] + [len(d["seeds"]) for d in datas])[:-1]
    data = {}
    for k in list(datas[0]):  # key by key, freeing each part once copied (the crops take GBs)
        data[k] = np.concatenate([d.pop(k) for d in datas])
    tr = np.c_[tr[:, 1] + offsets[tr[:, 0]], tr[:, 2:]]
    va = np.c_[va[:, 1] + offsets[va[:, 0]], va[:, 2:]]
    counts = np.bincount(tr[:, 2], minlength=len(CLASSES))
    log("training samples per class: " + ", ".join(f"{c} {n}" for c, n in zip(CLASSES, counts.tolist())))
    if counts[OTHER] == 0 or not counts[:OTHER].any():
        raise ValueError("no training samples of objects: render scenes first (`spark perception dataset`)")
    # balanced draws: every class seen in the data equally often, "other" as other_fraction of the batch
    present = int((counts[:OTHER] > 0).sum())
    p = np.where(tr[:, 2] == OTHER, cfg.other_fraction / counts[OTHER], 0.0)
    obj = tr[:, 2] != OTHER
    p[obj] = (1 - cfg.other_fraction) / present / counts[tr[obj, 2]]
    p /= p.sum()
    net = PatchNet()
    opt = torch.optim.AdamW(net.parameters(), lr=cfg.lr, weight_decay=1e-4)
    t0, step, run = time.perf_counter(), 0, None
    budget = cfg.minutes * 60
    while step < cfg.steps and time.perf_counter() - t0 < budget:
        frac = min(1.0, max(step / cfg.steps, (time.perf_counter() - t0) / budget))
        for g in opt.param_groups:
            g["lr"] = cfg.lr * 0.5 * (1 + np.cos(np.pi * frac))
        x, y = _batch(data, tr[rng.choice(len(tr), cfg.batch, p=p)], rng)
        loss = F.cross_entropy(net(x), y, label_smoothing=0.05)
        opt.zero_grad()
        loss.backward()
        opt.step()
        step += 1
        run = loss.item() if run is None else 0.95 * run + 0.05 * loss.item()
        if step % 100 == 0:
            log(f"step {step} ({time.perf_counter() - t0:.0f} s) loss {run:.3f}")
    elapsed = time.perf_counter() - t0
    val = accuracy(net, data, va)
    meta = {
        "config": asdict(cfg),
        "steps": step,
        "train_minutes": round(elapsed / 60, 2),
        "train_samples": int(len(tr)),
        "val_samples": int(len(va)),
        "val_accuracy": val,
        "final_loss": round(run or 0.0, 4),
    }
    save(net, Path(cfg.out), meta)
    log(json.dumps(meta))
    return meta
