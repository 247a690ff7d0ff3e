"""mask_pixels must be np.nonzero exactly (same rows, columns, order and dtype): the clean-ups' results depend on it."""

import numpy as np
import pytest

from spark_core.perception.pixels import mask_pixels


@pytest.mark.parametrize("shape", [(480, 640), (7, 3), (1, 9), (5, 1)])
def test_mask_pixels_equals_nonzero_in_order_and_dtype(shape):
    rng = np.random.default_rng(sum(shape))
    for density in (0.0, 0.03, 0.5, 1.0):
        mask = rng.random(shape) < density
        for m in (mask, mask.T.copy().T, np.asfortranarray(mask), mask.astype(np.int32) * 3):
            v, u = mask_pixels(m)
            ev, eu = np.nonzero(m)
            assert v.dtype == ev.dtype and u.dtype == eu.dtype
            np.testing.assert_array_equal(v, ev)
            np.testing.assert_array_equal(u, eu)


def test_mask_pixels_names_a_mask_that_is_not_2d():
    with pytest.raises(ValueError, match="2-D mask, got shape"):
        mask_pixels(np.zeros((2, 3, 4), bool))
