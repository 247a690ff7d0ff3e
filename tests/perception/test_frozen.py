"""frozen_forward: the traced, frozen channels-last graph gives the eager network's outputs (to float rounding),
keeps one graph per input shape (the per-pixel network's upsampling depends on it), leaves the network it was
given as it was, and never freezes a network in training."""

import copy

import torch

from spark_core.perception.learned import frozen
from spark_core.perception.learned.model import SegNet
from spark_core.perception.learned.patch_classifier import PatchNet


def _randomised(net: torch.nn.Module) -> torch.nn.Module:
    torch.manual_seed(0)
    for m in net.modules():  # batch-norm statistics away from the identity, so folding them is exercised
        if isinstance(m, torch.nn.BatchNorm2d):
            m.running_mean.uniform_(-0.5, 0.5)
            m.running_var.uniform_(0.5, 2.0)
            m.weight.data.uniform_(0.5, 1.5)
            m.bias.data.uniform_(-0.2, 0.2)
    return net.eval()


def test_segnet_graph_matches_eager_and_is_kept_per_shape():
    net = _randomised(SegNet(widths=(8, 8, 8, 8, 8), full_res=8))
    with torch.no_grad():
        for shape in ((1, 4, 64, 96), (1, 4, 96, 64), (1, 4, 64, 96)):
            x = torch.randn(shape)
            got, want = frozen.frozen_forward(net, x), net(x)
            assert got.shape == want.shape
            assert torch.allclose(got, want, atol=1e-4, rtol=1e-4), (got - want).abs().max()
            assert got.is_contiguous(memory_format=torch.channels_last)  # what the segmenter's softmax relies on
    assert set(frozen._GRAPHS[net]) == {(1, 4, 64, 96), (1, 4, 96, 64)}
    conv = next(m for m in net.modules() if isinstance(m, torch.nn.Conv2d) and m.kernel_size == (3, 3))
    assert conv.weight.is_contiguous()  # the graph converted a copy: the cached network keeps its own layout


def test_patch_classifier_graph_serves_every_batch_size():
    net = _randomised(PatchNet(widths=(8, 8, 8)))
    with torch.no_grad():
        for batch in (1, 5, 12):
            x = torch.randn(batch, 5, 48, 48)
            got, want = frozen.frozen_forward(net, x, batch_free=True), net(x)
            assert got.shape == (batch, len(net.classes))
            assert torch.allclose(got, want, atol=1e-4, rtol=1e-4)
    assert list(frozen._GRAPHS[net]) == [(5, 48, 48)]


def test_a_network_in_training_runs_eagerly_and_is_not_frozen():
    net = SegNet(widths=(8, 8, 8, 8, 8), full_res=8).train()
    x = torch.randn(2, 4, 64, 64)
    out = frozen.frozen_forward(net, x)
    assert out.shape[0] == 2 and out.requires_grad  # eager, with autograd: a frozen graph would hold stale weights
    assert net not in frozen._GRAPHS


def test_one_by_one_convolutions_run_as_onednn_pointwise_with_the_same_outputs():
    # torch sends a 1x1 convolution on one thread and a batch of one to its slow reference kernel; the graph runs
    # it through oneDNN instead (frozen.Pointwise), which must give what the convolution gives
    net = _randomised(SegNet(widths=(8, 8, 8, 8, 8), full_res=8))
    replaced = frozen._with_pointwise(copy.deepcopy(net))
    if torch.backends.mkldnn.is_available():
        assert isinstance(replaced.head, frozen.Pointwise) and isinstance(replaced.squeeze, frozen.Pointwise)
    assert not any(m.kernel_size == (1, 1) for m in replaced.modules() if isinstance(m, torch.nn.Conv2d))
    assert sum(isinstance(m, torch.nn.Conv2d) for m in replaced.modules()) == sum(
        isinstance(m, torch.nn.Conv2d) and m.kernel_size != (1, 1) for m in net.modules()
    )  # 3x3 convolutions untouched
    threads = torch.get_num_threads()
    torch.set_num_threads(1)  # the segmenter's setting, where torch picks the reference kernel
    try:
        x = torch.randn(1, 8, 24, 32).contiguous(memory_format=torch.channels_last)
        with torch.no_grad():
            got = frozen.Pointwise(net.head)(x)
            want = torch.nn.functional.conv2d(x, net.head.weight, net.head.bias)
    finally:
        torch.set_num_threads(threads)
    assert got.shape == want.shape and torch.allclose(got, want, atol=1e-5, rtol=1e-5)
    assert isinstance(net.head, torch.nn.Conv2d)  # the network it was given is left as it was
