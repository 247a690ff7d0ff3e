"""CameraFrame.height_map_m: the per-pixel world height the learned segmenter's clean-ups read, computed once per
frame, must equal backprojecting each pixel (and be NaN where the depth is missing)."""

import numpy as np
from scipy.spatial.transform import Rotation

from spark_core.perception.frame import CameraFrame


def test_height_map_equals_backprojected_heights_and_marks_missing_depth():
    rng = np.random.default_rng(0)
    T = np.eye(4)
    T[:3, :3] = Rotation.random(random_state=1).as_matrix()
    T[:3, 3] = [0.3, -0.2, 1.1]
    depth = rng.uniform(0.5, 2.0, (48, 64)).astype(np.float32)
    depth[3, 4], depth[5, 6], depth[7, 8] = 0.0, np.nan, np.inf
    K = np.array([[60.0, 0.0, 31.5], [0.0, 62.0, 23.5], [0.0, 0.0, 1.0]])
    frame = CameraFrame("c", np.zeros((48, 64, 3), np.uint8), depth, K, T)
    vs, us = np.mgrid[:48, :64]
    ok = np.isfinite(depth) & (depth > 0)
    expected = frame.backproject(us[ok].astype(float), vs[ok].astype(float), depth[ok])[:, 2]
    heights = frame.height_map_m
    np.testing.assert_allclose(heights[ok], expected, atol=1e-9)
    assert np.isnan(heights[~ok]).all() and (~ok).sum() == 3
    assert frame.height_map_m is heights  # cached: one map per frame
