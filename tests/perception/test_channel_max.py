"""channel_max must be torch's max(0) exactly (values, first index on ties, dtypes): the category map depends on it."""

import numpy as np
import pytest
import torch

from spark_core.perception.channel_max import channel_max


@pytest.mark.parametrize("shape", [(40, 24, 32), (1, 5, 7), (3, 1, 1)])
def test_channel_max_equals_torch_max_over_channels(shape):
    rng = np.random.default_rng(shape[0])
    logits = torch.from_numpy(rng.normal(size=shape).astype(np.float32))
    logits[shape[0] // 2 :] = -torch.inf if shape[0] > 2 else logits[shape[0] // 2 :]  # appended categories
    probs = torch.softmax(logits, 0)
    ties = torch.from_numpy(rng.integers(0, 3, size=shape).astype(np.float32))  # many equal maxima
    for scores in (probs, ties):
        want_v, want_i = scores.max(0)
        got_v, got_i = channel_max(scores.numpy())
        assert got_v.dtype == want_v.numpy().dtype and got_i.dtype == want_i.numpy().dtype
        np.testing.assert_array_equal(got_v, want_v.numpy())
        np.testing.assert_array_equal(got_i, want_i.numpy())


@pytest.mark.parametrize(
    "scores, match", [(np.zeros((4, 5)), "got shape"), (np.full((2, 2, 2), np.nan, np.float32), "NaN")]
)
def test_channel_max_names_what_is_wrong(scores, match):
    with pytest.raises(ValueError, match=match):
        channel_max(scores)
