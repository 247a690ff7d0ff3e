"""Inference graphs of the learned networks: a copy of the network in channels-last memory, traced and frozen by
torch.jit (batch norm folded into the convolutions). On this machine's CPU (AVX2, one thread) channels-last
convolutions run about a quarter faster than the default layout, and freezing saves a little more; the outputs
agree with eager mode to float rounding (about 1e-4 in the logits), which a test bounds.

1x1 convolutions call oneDNN's convolution directly (`Pointwise`): with one thread and a batch of one, torch's
dispatcher sends them to its slow reference kernel, which works in the default layout and copies the output back to
channels-last (profiled: the per-pixel network's 53-channel head cost 19 ms of a 37 ms forward that way); oneDNN's
result is bit-identical to it (a test checks).

`torch.jit.optimize_for_inference` is not used: it converts to oneDNN's own layout, and the per-pixel network's
upsampling and concatenation then convert back and forth (measured: slower than channels-last alone)."""

from __future__ import annotations

import copy
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


class Pointwise(nn.Module):
    """A 1x1, stride-1, ungrouped convolution run by oneDNN whatever the batch size and thread count (torch's
    dispatcher picks its slow reference kernel for these on one thread; see the module docstring)."""

    def __init__(self, conv: nn.Conv2d):
        super().__init__()
        self.weight = nn.Parameter(conv.weight.detach().clone(), requires_grad=False)
        self.bias = None if conv.bias is None else nn.Parameter(conv.bias.detach().clone(), requires_grad=False)

    def forward(self, x: torch.Tensor) -> torch.Tensor:
        return torch.ops.aten.mkldnn_convolution(x, self.weight, self.bias, [0, 0], [1, 1], [1, 1], 1)


def _is_pointwise(m: nn.Module) -> bool:
    return (
        isinstance(m, nn.Conv2d)
        and m.kernel_size == (1, 1)
        and m.stride == (1, 1)
        and m.groups == 1
        and m.dilation == (1, 1)
        and m.padding in ((0, 0), "valid")
    )


def _with_pointwise(net: nn.Module) -> nn.Module:
    """`net` (modified in place: call on a copy) with every 1x1 convolution replaced by `Pointwise` (when torch
    has oneDNN; otherwise as it was)."""
    if not torch.backends.mkldnn.is_available():
        return net
    for name, child in list(net.named_children()):
        if _is_pointwise(child):
            setattr(net, name, Pointwise(child))  # type: ignore[arg-type]  # a Conv2d child, checked above
        else:
            _with_pointwise(child)
    return net


def frozen_forward(net: nn.Module, x: torch.Tensor, batch_free: bool = False) -> torch.Tensor:
    """net(x) through a frozen channels-last trace of `net` (built on first use per input shape; eager mode for a
    network in training mode, which freezing would not allow).

    The result has the eager result's shape and values; a 4-D result is in channels-last memory (stride 1 along
    the channels): index it, never rely on `.view`. The per-pixel network's upsampling sizes come from its
    input's shape, so its graphs are kept per full shape; `batch_free`: the network's graph does not depend on
    the batch size (the patch classifier: convolutions, pooling and a mean), so one graph serves every batch. The
    graph holds the weights as they were when traced: only for loaded networks that are never trained again (the
    segmenter's and the classifier's weight caches). Call under torch.no_grad()."""
    if net.training:
        return net(x)
    key = tuple(x.shape[1:]) if batch_free else tuple(x.shape)
    x = x.contiguous(memory_format=torch.channels_last)
    with _LOCK:
        graphs = _GRAPHS.setdefault(net, {})
        graph = graphs.get(key)
        if graph is None:
            # a copy: the cached network itself stays as loaded (eager callers and training expect its layout)
            cl = _with_pointwise(copy.deepcopy(net)).to(memory_format=torch.channels_last)  # type: ignore[call-overload]
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")  # the tracer's notes on shape arithmetic: the key covers them
                graph = torch.jit.freeze(torch.jit.trace(cl, x, check_trace=False))
            graphs[key] = graph
    return graph(x)
