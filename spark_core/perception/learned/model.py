"""A compact RGB-D U-Net (plain torch, no torchvision): per-pixel category logits, an instance-boundary logit
and colour logits, all at input resolution."""

from __future__ import annotations

import cv2
import numpy as np
import torch
from torch import nn
from torch.nn import functional as F

from .categories import CATEGORIES, COLOURS

DEPTH_CENTRE_M, DEPTH_SCALE_M = 1.0, 0.5  # depth input = (depth - centre) / scale, clipped to [-3, 3]


def _block(c_in: int, c_out: int) -> nn.Sequential:
    return nn.Sequential(
        nn.Conv2d(c_in, c_out, 3, padding=1, bias=False),
        nn.BatchNorm2d(c_out),
        nn.ReLU(inplace=True),
        nn.Conv2d(c_out, c_out, 3, padding=1, bias=False),
        nn.BatchNorm2d(c_out),
        nn.ReLU(inplace=True),
    )


class SegNet(nn.Module):
    """Input (B, 4, H, W): RGB in [0, 1] and normalised depth; H and W multiples of 32.
    Output (B, n_categories + 1 + n_colours, H, W): category logits, boundary logit, colour logits."""

    def __init__(
        self,
        widths: tuple[int, ...] = (16, 32, 48, 64, 96),
        full_res: int = 16,
        downsample: int = 2,
        n_categories: int | None = None,  # default: every entry of CATEGORIES (older weights may have fewer)
    ):
        super().__init__()
        self.widths = tuple(widths)
        self.full_res = full_res
        self.downsample = downsample  # camera frames are shrunk by this factor before the network (see shrink)
        self.n_categories, self.n_colours = n_categories or len(CATEGORIES), len(COLOURS)
        # categories the weights were trained on (the first n_trained): fewer when categories were appended since
        # (train.load_net); the rest are never predicted
        self.n_trained = self.n_categories
        # The encoder starts at half resolution (a strided stem: full-resolution stages dominate CPU time); one
        # light full-resolution layer over the raw input sharpens the upsampled decoder output at mask edges.
        self.stem = nn.Sequential(
            nn.Conv2d(4, widths[0], 3, stride=2, padding=1, bias=False), nn.BatchNorm2d(widths[0]), nn.ReLU(True)
        )
        self.down = nn.ModuleList()
        c = widths[0]
        for w in widths:
            self.down.append(_block(c, w))
            c = w
        self.up = nn.ModuleList()
        for w in reversed(widths[:-1]):
            self.up.append(_block(c + w, w))
            c = w
        self.squeeze = nn.Conv2d(c, 8, 1)
        self.refine = nn.Sequential(
            nn.Conv2d(8 + 4, full_res, 3, padding=1, bias=False), nn.BatchNorm2d(full_res), nn.ReLU(True)
        )
        self.head = nn.Conv2d(full_res, self.n_categories + 1 + self.n_colours, 1)

    def forward(self, inp: torch.Tensor) -> torch.Tensor:
        skips = []
        x = self.stem(inp)
        for i, blk in enumerate(self.down):
            x = blk(x if i == 0 else F.max_pool2d(x, 2))
            skips.append(x)
        for blk, skip in zip(self.up, reversed(skips[:-1])):
            x = F.interpolate(x, size=skip.shape[-2:], mode="bilinear", align_corners=False)
            x = blk(torch.cat([x, skip], 1))
        x = F.interpolate(self.squeeze(x), size=inp.shape[-2:], mode="bilinear", align_corners=False)
        return self.head(self.refine(torch.cat([x, inp], 1)))

    def split(self, out: torch.Tensor) -> tuple[torch.Tensor, torch.Tensor, torch.Tensor]:
        """(category logits, boundary logit (B, H, W), colour logits)."""
        nc = self.n_categories
        return out[:, :nc], out[:, nc], out[:, nc + 1 :]


def network_input(rgb_u8: torch.Tensor, depth_m: torch.Tensor) -> torch.Tensor:
    """(B, H, W, 3) uint8 RGB and (B, H, W) depth (m) -> (B, 4, H, W) float input."""
    rgb = rgb_u8.permute(0, 3, 1, 2).float() / 255.0
    d = ((depth_m.float() - DEPTH_CENTRE_M) / DEPTH_SCALE_M).clamp(-3, 3).unsqueeze(1)
    return torch.cat([rgb, d], 1)


def shrink(rgb: np.ndarray, depth_m: np.ndarray, factor: int) -> tuple[np.ndarray, np.ndarray]:
    """A camera frame at 1/factor resolution, as the network sees it: RGB area-averaged, depth (and, in
    training, labels) by taking every factor-th pixel (never averaging across an object's edge)."""
    if factor == 1:
        return rgb, depth_m
    h, w = depth_m.shape[0] // factor, depth_m.shape[1] // factor
    small = cv2.resize(np.ascontiguousarray(rgb), (w, h), interpolation=cv2.INTER_AREA)
    return small, depth_m[: h * factor : factor, : w * factor : factor]
