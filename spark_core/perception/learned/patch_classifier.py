"""Second stage of the learned segmenter: a small CNN that names one object from a full-resolution patch around it.

The per-pixel network sees frames at half resolution, where LIBERO's grocery items (a few dozen pixels across,
printed labels telling them apart) look alike: it marks their pixels as *some* grocery item reliably but often
names the wrong one (see MODEL_CARD.md). So the segmenter takes every blob of pixels the per-pixel network puts
in GROUP, cuts it at boundaries and depth edges, and asks this classifier what it is, from the camera-resolution
RGB, the blob's mask and its depth relief; and it takes a second look at every other whole object the per-pixel
network found (a plate on a stove it called stove). CLASSES: every whole-object category (parts, which are only
ever seen on their parent, are left to the per-pixel network) and "other" (a shadow, a part, the floor).

Camera-only: the input is RGB, depth and a mask the segmenter itself predicted.
"""

from __future__ import annotations

import threading
from importlib import resources
from pathlib import Path
from typing import Any

import cv2
import numpy as np
import torch
from torch import nn

from .categories import CATEGORIES, CATEGORY_INDEX
from .frozen import frozen_forward

PATCH_PX = 48  # side of the square network input
MARGIN = 0.25  # context around the mask's bounding box, as a fraction of its longer side
DEPTH_RELIEF_M = 0.1  # depth channel = (depth - the mask's median depth) / this, clipped to [-2, 2]
GROUP: tuple[str, ...] = (
    "cream cheese",
    "ramekin",
    "cookie box",
    "alphabet soup",
    "bbq sauce",
    "butter",
    "chocolate pudding",
    "ketchup",
    "milk",
    "orange juice",
    "salad dressing",
    "tomato sauce",
)
CLASSES: tuple[str, ...] = (*(c.name for c in CATEGORIES if c.thing and not c.part_of), "other")
OTHER = len(CLASSES) - 1
CLASS_CATEGORY = np.array([CATEGORY_INDEX[n] for n in CLASSES[:OTHER]])  # class index -> category index
GROUP_INDEX = np.array([CATEGORY_INDEX[n] for n in GROUP])
WEIGHTS = "weights/patch_classifier.pt"
_NETS: dict[str, Any] = {}
_LOCK = threading.Lock()


def square_box(mask: np.ndarray, margin: float = MARGIN) -> tuple[int, int, int, int] | None:
    """(row0, col0, side) of a square window around the mask's bounding box with `margin` context, and the
    box's longer side (px); None for an empty mask. The window may reach past the image (padded when cut)."""
    # OpenCV's bounding box of the nonzero pixels: the same box as their min/max indices, without listing them
    c0, r0, w, h = cv2.boundingRect(_as_u8(mask))
    if w == 0 or h == 0:
        return None
    r1, c1 = r0 + h, c0 + w
    side = int(max(h, w))
    win = int(np.ceil(side * (1 + 2 * margin))) + 4
    return int((r0 + r1 - win) // 2), int((c0 + c1 - win) // 2), win, side


def patch(
    rgb: np.ndarray, depth_m: np.ndarray, mask: np.ndarray, window: tuple[int, int, int] | None = None
) -> np.ndarray | None:
    """(5, PATCH_PX, PATCH_PX) float32 network input for the object under `mask` (all arrays at camera
    resolution): RGB in [0, 1], the mask, the depth relief around the mask's median depth. `window` =
    (row0, col0, side) overrides the box (training jitters it). None for an empty mask."""
    if window is None:
        box = square_box(mask)
        if box is None:
            return None
        window = box[:3]
    r0, c0, win = window
    m = _window(_as_u8(mask), r0, c0, win).astype(bool)
    if not m.any():
        return None
    size = (PATCH_PX, PATCH_PX)
    img = cv2.resize(_window(rgb, r0, c0, win), size, interpolation=cv2.INTER_AREA).astype(np.float32) / 255.0
    d = np.nan_to_num(_window(depth_m, r0, c0, win).astype(np.float32), nan=0.0, posinf=10.0)
    ref = float(np.median(d[m]))
    rel = np.clip((d - ref) / DEPTH_RELIEF_M, -2, 2)
    rel = cv2.resize(rel, size, interpolation=cv2.INTER_NEAREST)
    mk = cv2.resize(m.astype(np.float32), size, interpolation=cv2.INTER_AREA)
    return np.concatenate([img.transpose(2, 0, 1), mk[None], rel[None]]).astype(np.float32)


def _as_u8(mask: np.ndarray) -> np.ndarray:
    """A 2-D mask as 0/1 uint8 (a bool mask is viewed, not copied)."""
    return np.ascontiguousarray(mask if mask.dtype == bool else mask != 0).view(np.uint8)


def _window(image: np.ndarray, r0: int, c0: int, win: int) -> np.ndarray:
    """The (win, win) window of `image` at row r0, column c0; where it reaches past the image, zeros (black, no
    mask, far depth) so the object stays centred. Only the window is copied and padded, not the frame."""
    H, W = image.shape[:2]
    rr0, rr1, cc0, cc1 = max(r0, 0), min(r0 + win, H), max(c0, 0), min(c0 + win, W)
    if rr1 <= rr0 or cc1 <= cc0:  # wholly outside
        return np.zeros((win, win, *image.shape[2:]), image.dtype)
    crop = np.ascontiguousarray(image[rr0:rr1, cc0:cc1])
    top, bottom, left, right = rr0 - r0, r0 + win - rr1, cc0 - c0, c0 + win - cc1
    if not (top or bottom or left or right):
        return crop
    return cv2.copyMakeBorder(crop, top, bottom, left, right, cv2.BORDER_CONSTANT, value=0)


def _conv(c_in: int, c_out: int) -> nn.Sequential:
    return nn.Sequential(nn.Conv2d(c_in, c_out, 3, padding=1, bias=False), nn.BatchNorm2d(c_out), nn.ReLU(True))


class PatchNet(nn.Module):
    """(B, 5, PATCH_PX, PATCH_PX) -> (B, len(classes)) logits. `classes` is CLASSES unless the weights were
    trained before categories were appended; `to_current` maps its outputs onto CLASSES by name."""

    def __init__(self, widths: tuple[int, int, int] = (24, 48, 96), classes: tuple[str, ...] = CLASSES):
        super().__init__()
        self.widths = tuple(widths)
        self.classes = tuple(classes)
        self.to_current = np.array([CLASSES.index(c) for c in self.classes])
        layers: list[nn.Module] = [_conv(5, widths[0]), nn.MaxPool2d(2)]  # one conv at full size: most of the cost
        c = widths[0]
        for w in widths[1:]:
            layers += [_conv(c, w), _conv(w, w), nn.MaxPool2d(2)]
            c = w
        self.features = nn.Sequential(*layers)
        self.head = nn.Sequential(nn.Dropout(0.2), nn.Linear(c, len(self.classes)))

    def forward(self, x: torch.Tensor) -> torch.Tensor:
        return self.head(self.features(x).mean((2, 3)))


def default_weights() -> Path:
    return Path(str(resources.files(__package__).joinpath(WEIGHTS)))


def save(net: PatchNet, path: Path, meta: dict) -> None:
    """float16 weights with the architecture, the class list and training metadata."""
    path.parent.mkdir(parents=True, exist_ok=True)
    state = {k: (v.half() if v.is_floating_point() else v) for k, v in net.state_dict().items()}
    torch.save({"widths": net.widths, "classes": list(net.classes), "state": state, "meta": meta}, path)


def load(path: Path) -> PatchNet:
    """Weights file -> network in eval mode (cached per path); a clear error for a missing file or one trained
    for a class list that is not a subset of this version's (categories are only ever appended: older weights
    keep naming what they know and never name an appended category)."""
    key = str(path)
    with _LOCK:
        if key not in _NETS:
            if not path.is_file():
                raise FileNotFoundError(
                    f"patch classifier weights not found at {path}: train them with `spark perception train-patches`"
                )
            ckpt = torch.load(path, map_location="cpu", weights_only=True)
            classes = tuple(ckpt["classes"])
            unknown = [c for c in classes if c not in CLASSES]
            if unknown or classes[-1] != CLASSES[OTHER]:
                raise ValueError(f"{path} classifies {list(classes)}; not in this version's classes: {unknown}")
            net = PatchNet(tuple(ckpt["widths"]), classes)
            net.load_state_dict({k: v.float() if v.is_floating_point() else v for k, v in ckpt["state"].items()})
            _NETS[key] = net.eval()
        return _NETS[key]


def classify(net: PatchNet, patches: list[np.ndarray]) -> np.ndarray:
    """(N, len(CLASSES)) class probabilities of N patches (one thread: see LearnedSegmenter.predict); a class
    the weights do not know gets 0."""
    out = np.zeros((len(patches), len(CLASSES)), np.float32)
    if not patches:
        return out
    threads = torch.get_num_threads()
    torch.set_num_threads(1)
    try:
        with torch.no_grad():
            logits = frozen_forward(net, torch.from_numpy(np.stack(patches)), batch_free=True)
            out[:, net.to_current] = torch.softmax(logits, 1).numpy()
            return out
    finally:
        torch.set_num_threads(threads)
