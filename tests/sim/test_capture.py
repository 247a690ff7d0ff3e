"""Episode capture: image statistics from histograms equal the direct computation; a bad configuration is
refused with what was wrong."""

import numpy as np
import pytest

from spark_core.sim.capture import CaptureConfig, _image_stats


def test_image_stats_match_numpy_exactly():
    rng = np.random.default_rng(3)
    frames = [rng.integers(0, 256, (32, 48, 3), dtype=np.uint8) for _ in range(4)]
    frames[0][..., 2] = 7  # a channel with a narrow range
    st = {k: np.array(v, float).ravel() for k, v in _image_stats(frames).items()}
    x = np.stack(frames).reshape(-1, 3) / 255.0
    for name, ref in (("min", x.min(0)), ("max", x.max(0)), ("mean", x.mean(0)), ("std", x.std(0))):
        np.testing.assert_allclose(st[name], ref, atol=1e-12, err_msg=name)
    assert st["count"].tolist() == [4] and np.array(_image_stats(frames)["mean"]).shape == (3, 1, 1)


@pytest.mark.parametrize("kw,msg", [({"fps": 0.5}, "fps must be in"), ({"width": 100}, "multiples of 8")])
def test_bad_capture_settings_are_named(kw, msg):
    with pytest.raises(ValueError, match=msg):
        CaptureConfig(**kw)
