"""last_axis_max must be torch's max(-1) exactly (values, first index on ties, dtypes): the category map depends on
it."""

import numpy as np
import pytest
import torch

from spark_core.perception.last_axis_max import last_axis_max


@pytest.mark.parametrize("shape", [(24, 32, 40), (5, 7, 1), (1, 1, 3)])
def test_last_axis_max_equals_torch_max_over_the_last_axis(shape):
    rng = np.random.default_rng(shape[-1])
    logits = torch.from_numpy(rng.normal(size=shape).astype(np.float32))
    if shape[-1] > 2:
        logits[..., shape[-1] // 2 :] = -torch.inf  # appended categories
    probs = torch.softmax(logits, -1)
    ties = torch.from_numpy(rng.integers(0, 3, size=shape).astype(np.float32))  # many equal maxima
    for scores in (probs, ties):
        want_v, want_i = scores.max(-1)
        got_v, got_i = last_axis_max(scores.numpy())
        assert got_v.dtype == want_v.numpy().dtype and got_i.dtype == want_i.numpy().dtype
        np.testing.assert_array_equal(got_v, want_v.numpy())
        np.testing.assert_array_equal(got_i, want_i.numpy())


def test_a_strided_view_gives_the_same_as_a_copy():
    rng = np.random.default_rng(1)
    chw = rng.integers(0, 4, size=(12, 9, 11)).astype(np.float32)
    view = chw.transpose(1, 2, 0)  # (h, w, C) over (C, h, w) memory
    for got, want in zip(last_axis_max(view), last_axis_max(np.ascontiguousarray(view))):
        np.testing.assert_array_equal(got, want)


@pytest.mark.parametrize(
    "scores, match", [(np.zeros((4, 5)), "got shape"), (np.full((2, 2, 2), np.nan, np.float32), "NaN")]
)
def test_last_axis_max_names_what_is_wrong(scores, match):
    with pytest.raises(ValueError, match=match):
        last_axis_max(scores)
