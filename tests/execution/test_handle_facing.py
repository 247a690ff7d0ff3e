"""Which way a drawer handle faces (the way its drawer opens), from where it sits on what it belongs to, as a
camera-only segmenter sees them: a handle seen only at one end, a drawer front a few mm deep, a cabinet."""

import numpy as np

from spark_core.execution.primitives.articulated import facing_from_wholes
from spark_core.perception import Keypoint


def _kp(label, xyz, extent, yaw=None):
    return Keypoint(label, np.array(xyz, float), np.array(extent, float), yaw_rad=yaw)


def test_a_handle_seen_near_the_end_of_a_drawer_front_faces_out_of_the_front():
    """LIBERO's cabinet opens toward +y. The handle's visible end lies 1.2 cm along the front (x) from the front's
    centre and 0.8 cm out of it (y): the bare offset says -x, the face test says +y."""
    front = _kp("drawer top layer", (0.728, -0.145, 0.186), (0.131, 0.002, 0.054), yaw=0.0)
    handle = _kp("drawer top layer handle", (0.716, -0.137, 0.19), (0.027, 0.028, 0.015))
    assert np.allclose(facing_from_wholes(handle, [front]), [0.0, 1.0, 0.0])


def test_the_cabinet_decides_when_a_drawer_is_seen_as_a_blob():
    """Builtin cabinet opening toward the robot (-x): a drawer mask that spilled sideways (its centre 5.5 cm to
    one side of the handle) would say +y; the cabinet, 12 cm behind the handle and 0.6 cm to the side, says -x."""
    drawer = _kp("cabinet drawer", (0.671, 0.145, 0.085), (0.162, 0.139, 0.17))
    cabinet = _kp("cabinet", (0.77, 0.194, 0.086), (0.206, 0.265, 0.169), yaw=-np.pi / 2)
    handle = _kp("cabinet drawer handle", (0.65, 0.2, 0.1), (0.039, 0.009, 0.051))
    assert np.allclose(facing_from_wholes(handle, [drawer, cabinet]), [-1.0, 0.0, 0.0], atol=1e-9)


def test_no_whole_or_a_part_at_its_centre_faces_the_robot():
    handle = _kp("handle", (0.5, 0.0, 0.1), (0.03, 0.01, 0.02))
    assert np.allclose(facing_from_wholes(handle, []), [-1.0, 0.0, 0.0])
    assert np.allclose(facing_from_wholes(handle, [_kp("box", (0.5, 0.001, 0.1), (0.2, 0.2, 0.2))]), [-1, 0, 0])
