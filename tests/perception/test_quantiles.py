"""percentiles must be np.percentile exactly (bit for bit): the learned segmenter's clean-ups compare these numbers
with thresholds, so a last-digit difference could change a mask."""

import numpy as np
import pytest

from spark_core.perception.quantiles import percentile, percentiles, percentiles_of_sorted

QS = (0, 2, 5, 25, 50, 75, 95, 98, 100, 33.3, 99.99, 0.01)


@pytest.mark.parametrize("dtype", [np.float64, np.float32])
@pytest.mark.parametrize("cols", [None, 1, 2, 3])
def test_percentiles_equal_numpy_bit_for_bit(dtype, cols):
    rng = np.random.default_rng(7 if cols is None else cols)
    for n in list(range(1, 40)) + [97, 500, 4001]:
        shape = (n,) if cols is None else (n, cols)
        for values in (
            rng.normal(0.4, 0.3, shape).astype(dtype),
            rng.integers(0, 4, shape).astype(dtype) * 0.1,  # many ties
            (rng.random(shape) * 1e-3 + 0.81).astype(dtype),  # world heights: close, large numbers
        ):
            got = percentiles(values, QS)
            for q, g in zip(QS, got):
                want = np.percentile(values, q, axis=0)
                assert g.dtype == want.dtype and g.shape == np.shape(want)
                assert np.array_equal(g, want), (n, q, g, want)
            assert np.array_equal(percentile(values, 98), np.percentile(values, 98, axis=0))
            if dtype == np.float64:  # q given as a sequence: numpy interpolates with an array weight, same numbers
                lo, hi = np.percentile(values, (5.0, 95.0), axis=0)
                got_lo, got_hi = percentiles(values, (5.0, 95.0))
                assert np.array_equal(got_lo, lo) and np.array_equal(got_hi, hi)


@pytest.mark.parametrize("dtype", [np.float64, np.float32])
def test_percentiles_of_sorted_columns_equal_numpy_bit_for_bit(dtype):
    """As _rejoin uses it: two point sets, each sorted per column, joined by a stable sort (a merge of two runs)."""
    rng = np.random.default_rng(3)
    for na, nb in [(1, 1), (1, 5), (7, 3), (60, 2000), (1500, 1700)]:
        a = rng.normal(0.2, 0.1, (na, 2)).astype(dtype)
        b = (rng.integers(0, 5, (nb, 2)) * 0.05).astype(dtype)  # ties within b and with a
        joined = np.sort(np.concatenate([np.sort(a, axis=0), np.sort(b, axis=0)]), axis=0, kind="stable")
        for q, got in zip(QS, percentiles_of_sorted(joined, QS)):
            want = np.percentile(np.concatenate([a, b]), q, axis=0)
            assert got.dtype == want.dtype and np.array_equal(got, want), (na, nb, q)


def test_percentiles_leave_the_input_unchanged():
    values = np.random.default_rng(0).random((50, 2))
    before = values.copy()
    percentiles(values, (2, 98))
    assert np.array_equal(values, before)


@pytest.mark.parametrize(
    "values, qs, match",
    [
        (np.zeros(0), (50,), "empty"),
        (np.array([1.0, np.nan]), (50,), "NaN"),
        (np.ones(3), (101,), "outside 0..100"),
        (np.ones(3), (-1,), "outside 0..100"),
    ],
)
def test_percentiles_name_what_is_wrong(values, qs, match):
    with pytest.raises(ValueError, match=match):
        percentiles(values, qs)
