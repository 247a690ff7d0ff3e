"""Train the learned segmenter on a rendered dataset (see dataset.py): cross-entropy on categories and colours,
binary cross-entropy on instance boundaries, random crops and flips, a wall-time or step budget."""

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

from .categories import CATEGORIES, COLOURS
from .dataset import load_shards
from .model import SegNet, network_input, shrink

THING_WEIGHT = 3.0  # category loss weight of object pixels (few, and what matters) relative to background


@dataclass(frozen=True)
class TrainConfig:
    data_dirs: tuple[str, ...]  # trained together; each holds out its own highest-seed crops for validation
    out: str  # weights file (.pt)
    steps: int = 100_000
    minutes: float = 45.0  # wall-time budget; training stops at whichever of steps/minutes comes first
    batch: int = 12
    crop: tuple[int, int] = (192, 256)  # (height, width) of the random training crops, camera resolution
    downsample: int = 2  # crops (and, at inference, frames) are shrunk by this factor before the network
    lr: float = 2e-3
    seed: int = 0
    val_fraction: float = 0.05  # the dataset's last crops (highest scene seeds) held out for validation
    threads: int = 2
    init: str | None = None  # weights to start from (a fine-tuning run) instead of random initialisation
    balance: bool = False  # weight object categories by rarity (sqrt of median/own pixel frequency)
    balance_max: float = 8.0  # the largest rarity up-weighting
    oversample_rare: bool = False  # draw crops showing a rare category more often (by its rarity weight)


def boundary_target(instance: np.ndarray, band_px: int = 2) -> np.ndarray:
    """Pixels of an object within `band_px` of a DIFFERENT object (where two touching instances must be split)."""
    k = np.ones((2 * band_px + 1, 2 * band_px + 1), np.uint8)
    inst = instance.astype(np.uint8)
    hi = cv2.dilate(inst, k)
    lo = cv2.erode(np.where(inst == 0, 255, inst).astype(np.uint8), k)
    return (inst > 0) & (((hi != inst) & (hi > 0)) | ((lo != inst) & (lo < 255)))


def _batch(data: dict[str, np.ndarray], idx: np.ndarray, crop: tuple[int, int], rng: np.random.Generator, factor: int):
    h, w = crop
    H, W = data["category"].shape[1:]
    rgb, depth, cat, bnd, col = [], [], [], [], []
    for i in idx:
        r0, c0 = int(rng.integers(0, H - h + 1)), int(rng.integers(0, W - w + 1))
        win = (slice(r0, r0 + h), slice(c0, c0 + w))
        flip = rng.random() < 0.5
        f = (lambda a: a[:, ::-1]) if flip else (lambda a: a)
        im, d = shrink(f(data["rgb"][i][win]), f(data["depth_mm"][i][win]), factor)
        im = im.astype(np.float32) * rng.uniform(0.75, 1.25) + rng.normal(0, 6, 3)  # lighting, white balance
        rgb.append(np.clip(im, 0, 255).astype(np.uint8))
        depth.append(d.astype(np.float32) / 1000.0)
        # labels sampled like depth (see shrink)
        c, inst, co = (f(data[k][i][win])[::factor, ::factor] for k in ("category", "instance", "colour"))
        cat.append(c)
        bnd.append(boundary_target(np.ascontiguousarray(inst), max(1, 2 // factor)))
        col.append(co)
    t = lambda xs, dt: torch.from_numpy(np.ascontiguousarray(np.stack(xs))).to(dt)
    return (
        network_input(t(rgb, torch.uint8), t(depth, torch.float32)),
        t(cat, torch.long),
        t(bnd, torch.float32),
        t(col, torch.long),
    )


def category_weights(category: np.ndarray | list[np.ndarray] | None = None, max_factor: float = 8.0) -> torch.Tensor:
    """Cross-entropy weight per category: THING_WEIGHT for objects, 1 for background/table/robot; with the
    datasets' category maps, rare object categories (small parts) weigh up to `max_factor` more than that. Rarity
    is judged within each dataset and the largest factor kept: the builtin drawer handle stays rare even where
    LIBERO's big cabinets bring many handle pixels."""
    weight = torch.ones(len(CATEGORIES))
    things = [i for i, c in enumerate(CATEGORIES) if c.thing]
    weight[things] = THING_WEIGHT
    for cats in [category] if isinstance(category, np.ndarray) else category or []:
        freq = np.bincount(cats.ravel(), minlength=len(CATEGORIES)).astype(float)
        present = [i for i in things if freq[i] > 0]
        median = np.median(freq[present]) if present else 0.0
        for i in present:
            factor = float(np.clip(np.sqrt(median / freq[i]), 1.0, max_factor))
            weight[i] = max(float(weight[i]), THING_WEIGHT * factor)
    return weight


def crop_rarity(category: np.ndarray, weight: torch.Tensor, min_px: int = 20) -> np.ndarray:
    """Per crop: the largest rarity factor (category weight / THING_WEIGHT, >= 1) of the object categories it
    shows at least `min_px` pixels of; crops are then drawn in proportion (small parts seen more often)."""
    factor = np.maximum(weight.numpy() / THING_WEIGHT, 1.0)
    factor[[i for i, c in enumerate(CATEGORIES) if not c.thing]] = 1.0
    out = np.ones(len(category))
    for i, crop in enumerate(category):
        present = np.bincount(crop.ravel(), minlength=len(CATEGORIES)) >= min_px
        out[i] = factor[present].max() if present.any() else 1.0
    return out


def losses(net: SegNet, x, cat, bnd, col, weight: torch.Tensor | None = None) -> dict[str, torch.Tensor]:
    cat_logits, bnd_logit, col_logits = net.split(net(x))
    weight = category_weights() if weight is None else weight
    obj = col > 0
    out = {
        "category": F.cross_entropy(cat_logits, cat, weight=weight),
        "boundary": F.binary_cross_entropy_with_logits(bnd_logit, bnd, pos_weight=torch.tensor(4.0)),
        "colour": F.cross_entropy(col_logits.permute(0, 2, 3, 1)[obj], col[obj]) if obj.any() else cat_logits.sum() * 0,
    }
    out["total"] = out["category"] + 0.5 * out["boundary"] + 0.5 * out["colour"]
    return out


def thing_iou(net: SegNet, data: dict[str, np.ndarray], idx: np.ndarray) -> dict[str, float]:
    """Pixel IoU per object category over the validation crops (whole crops at network resolution)."""
    net.eval()
    inter = np.zeros(net.n_categories)
    union = np.zeros(net.n_categories)
    with torch.no_grad():
        for i in idx:
            im, d = shrink(data["rgb"][i], data["depth_mm"][i], net.downsample)
            x = network_input(torch.from_numpy(im[None]), torch.from_numpy(d[None].astype(np.float32) / 1000))
            pred = net.split(net(x))[0].argmax(1).numpy()[0]
            gt = data["category"][i][:: net.downsample, :: net.downsample]
            for c in range(net.n_categories):
                p, g = pred == c, gt == c
                inter[c] += (p & g).sum()
                union[c] += (p | g).sum()
    net.train()
    return {CATEGORIES[c].name: round(float(inter[c] / union[c]), 4) for c in range(net.n_categories) if union[c] > 0}


def save(net: SegNet, path: Path, meta: dict) -> None:
    """Weights in float16 (half the bytes; inference casts back) with the architecture and training metadata."""
    path.parent.mkdir(parents=True, exist_ok=True)
    state = {k: (v.half() if v.is_floating_point() else v) for k, v in net.state_dict().items()}
    arch = {"widths": net.widths, "full_res": net.full_res, "downsample": net.downsample}
    torch.save({**arch, "state": state, "meta": meta}, path)


def train(cfg: TrainConfig, log: Callable[[str], None] = print) -> dict:
    torch.manual_seed(cfg.seed)
    torch.set_num_threads(cfg.threads)
    rng = np.random.default_rng(cfg.seed)
    if not cfg.data_dirs:
        raise ValueError("no dataset directory given")
    parts = [load_shards(Path(d)) for d in cfg.data_dirs]
    shapes = {p["category"].shape[1:] for p in parts}
    if len(shapes) > 1:
        raise ValueError(f"the datasets' crops differ in size ({sorted(shapes)}): render them with one crop size")
    sizes = [len(p["seeds"]) for p in parts]
    data = {}
    for k in list(parts[0]):  # key by key, freeing each part's array once copied (the crops take GBs)
        data[k] = np.concatenate([p.pop(k) for p in parts])
    if cfg.crop[0] > data["category"].shape[1] or cfg.crop[1] > data["category"].shape[2]:
        raise ValueError(f"crop {cfg.crop} is larger than the dataset's crops {data['category'].shape[1:]}")
    train_parts, val_parts, start = [], [], 0
    for d, n in zip(cfg.data_dirs, sizes):  # each dataset's highest seeds are its validation crops
        order = start + np.argsort(data["seeds"][start : start + n], kind="stable")
        n_val = max(1, int(len(order) * cfg.val_fraction)) if len(order) > 1 else 0
        if len(order) - n_val == 0:
            raise ValueError(f"dataset {d} has too few crops ({len(order)}) to train on")
        train_parts.append(order[: len(order) - n_val])
        val_parts.append(order[len(order) - n_val :])
        start += n
    train_idx, val_idx = np.concatenate(train_parts), np.concatenate(val_parts)
    log(f"{len(train_idx)} training crops, {len(val_idx)} validation crops")
    if cfg.init:
        net = load_net(Path(cfg.init)).train()
        net.n_trained = net.n_categories  # the appended categories' rows are trained from here on
        if net.downsample != cfg.downsample:
            raise ValueError(f"--init weights see frames shrunk {net.downsample}x, not {cfg.downsample}x")
    else:
        net = SegNet(downsample=cfg.downsample)
    bounds = np.cumsum([0, *sizes])
    per_dataset = [data["category"][a:b] for a, b in zip(bounds[:-1], bounds[1:])]
    weight = category_weights(per_dataset if cfg.balance else None, cfg.balance_max)
    log("category weights: " + ", ".join(f"{c.name} {w:.1f}" for c, w in zip(CATEGORIES, weight.tolist())))
    draw_p = None
    if cfg.oversample_rare:
        rarity = crop_rarity(data["category"][train_idx], weight)
        draw_p = rarity / rarity.sum()
        log(f"oversampling rare categories: crop draw weights 1..{rarity.max():.1f}, mean {rarity.mean():.2f}")
    opt = torch.optim.AdamW(net.parameters(), lr=cfg.lr, weight_decay=1e-4)
    t0 = time.perf_counter()
    budget_s = cfg.minutes * 60
    step, seen = 0, 0
    run: dict[str, float] = {}
    while step < cfg.steps and time.perf_counter() - t0 < budget_s:
        frac = min(1.0, max(step / cfg.steps, (time.perf_counter() - t0) / budget_s))
        for g in opt.param_groups:  # cosine decay over whichever budget runs out first
            g["lr"] = cfg.lr * 0.5 * (1 + np.cos(np.pi * frac))
        idx = rng.choice(train_idx, size=min(cfg.batch, len(train_idx)), replace=False, p=draw_p)
        x, cat, bnd, col = _batch(data, idx, cfg.crop, rng, cfg.downsample)
        loss = losses(net, x, cat, bnd, col, weight)
        opt.zero_grad()
        loss["total"].backward()
        opt.step()
        step += 1
        seen += len(idx)
        for k, v in loss.items():
            run[k] = 0.95 * run.get(k, v.item()) + 0.05 * v.item()
        if step % 50 == 0:
            el = time.perf_counter() - t0
            log(f"step {step} ({el:.0f} s, {seen / el:.1f} img/s) " + " ".join(f"{k} {v:.3f}" for k, v in run.items()))
        if step % 1000 == 0:
            save(net, Path(cfg.out), {"config": asdict(cfg), "steps": step, "partial": True})
    elapsed = time.perf_counter() - t0
    val = {Path(d).name: thing_iou(net, data, v) for d, v in zip(cfg.data_dirs, val_parts) if len(v)}
    meta = {
        "config": asdict(cfg),
        "steps": step,
        "images_seen": seen,
        "train_minutes": round(elapsed / 60, 2),
        "train_crops": int(len(train_idx)),
        "val_crops": int(len(val_idx)),
        "val_pixel_iou": val,
        "final_loss": {k: round(v, 4) for k, v in run.items()},
    }
    save(net, Path(cfg.out), meta)
    log(json.dumps(meta))
    return meta


def load_net(path: Path) -> SegNet:
    """Weights -> network with a head for every current category: weights saved with fewer categories (before
    categories were appended) get new head rows (see expand_categories)."""
    ckpt = torch.load(path, map_location="cpu", weights_only=True)
    state = {k: v.float() if v.is_floating_point() else v for k, v in ckpt["state"].items()}
    n_saved = int(state["head.weight"].shape[0]) - 1 - len(COLOURS)
    if n_saved > len(CATEGORIES):
        raise ValueError(f"{path} predicts {n_saved} categories, more than the {len(CATEGORIES)} of categories.py")
    net = SegNet(tuple(ckpt["widths"]), int(ckpt["full_res"]), int(ckpt["downsample"]))
    net.load_state_dict(expand_categories(state, n_saved, len(CATEGORIES)))
    net.n_trained = n_saved
    return net.eval()


def expand_categories(state: dict[str, torch.Tensor], n_old: int, n_new: int) -> dict[str, torch.Tensor]:
    """A state dict whose head predicts `n_old` categories -> one predicting `n_new` (categories are only ever
    appended, so the first n_old keep their rows). A new category's row starts as the mean of the object rows
    with its bias lowered by 2 (rare until trained); the boundary and colour rows move down unchanged."""
    if n_old == n_new:
        return state
    w, b = state["head.weight"], state["head.bias"]
    things = [i for i in range(n_old) if CATEGORIES[i].thing]
    k = n_new - n_old
    w_new = w[things].mean(0, keepdim=True).repeat(k, 1, 1, 1)
    b_new = b[things].mean().repeat(k) - 2.0
    out = dict(state)
    out["head.weight"] = torch.cat([w[:n_old], w_new, w[n_old:]], 0)
    out["head.bias"] = torch.cat([b[:n_old], b_new, b[n_old:]], 0)
    return out
