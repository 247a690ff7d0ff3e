"""Inference graphs of the learned networks: traced, frozen and optimised by torch.jit (batch norm folded into the
convolutions, oneDNN kernels). On this machine's CPU the per-pixel network's forward pass takes about a quarter
less time and the patch classifier's about a third less than in eager mode; the outputs agree with eager mode to
float rounding (about 1e-4 in the logits), which a test bounds."""

from __future__ import annotations

import threading
import warnings
import weakref
from collections.abc import Callable

import torch
from torch import nn

_LOCK = threading.Lock()
# per network: traced graph per input shape key (the network object is the weights' cache entry: it lives as long
# as they are loaded)
_GRAPHS: weakref.WeakKeyDictionary[nn.Module, dict[tuple[int, ...], Callable[[torch.Tensor], torch.Tensor]]]
_GRAPHS = weakref.WeakKeyDictionary()


def frozen_forward(net: nn.Module, x: torch.Tensor, batch_free: bool = False) -> torch.Tensor:
    """net(x) through a frozen, inference-optimised trace of `net` (built on first use per input shape; eager
    mode for a network in training mode, which freezing would not allow).

    The per-pixel network's upsampling sizes come from its input's shape, so its graphs are kept per full shape;
    `batch_free`: the network's graph does not depend on the batch size (the patch classifier: convolutions,
    pooling and a mean), so one graph serves every batch. The graph holds the weights as they were when traced:
    only for loaded networks that are never trained again (the segmenter's and the classifier's weight caches).
    Call under torch.no_grad()."""
    if net.training:
        return net(x)
    key = tuple(x.shape[1:]) if batch_free else tuple(x.shape)
    with _LOCK:
        graphs = _GRAPHS.setdefault(net, {})
        graph = graphs.get(key)
        if graph is None:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")  # the tracer's notes on shape arithmetic: the key covers them
                traced = torch.jit.trace(net, x, check_trace=False)
                graph = torch.jit.optimize_for_inference(torch.jit.freeze(traced))
            graphs[key] = graph
    return graph(x)
