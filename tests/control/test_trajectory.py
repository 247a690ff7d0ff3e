"""ruckig segments chained through via points: limits respected, waypoints hit, no stop at aligned vias."""

import numpy as np

from spark_core.control import Limits, chain_joint_waypoints, line_trajectory

LIM = Limits(np.full(2, 1.0), np.full(2, 4.0), np.full(2, 40.0))


def test_chain_hits_waypoints_and_respects_limits():
    pts = [np.zeros(2), np.array([0.5, 0.2]), np.array([1.0, 0.4]), np.array([1.2, -0.2])]
    traj = chain_joint_waypoints(pts, LIM, dt_s=0.01)
    np.testing.assert_allclose(traj.q_rad[-1], pts[-1], atol=1e-6)
    assert np.all(np.abs(traj.qd_rad_s) <= 1.0 + 1e-6)
    for p in pts[1:-1]:  # passes within 1 mrad of every via point
        assert np.min(np.linalg.norm(traj.q_rad - p, axis=1)) < 2e-2
    acc = np.diff(traj.qd_rad_s, axis=0) / 0.01
    assert np.all(np.abs(acc) <= 4.0 * 1.05)


def test_aligned_via_point_keeps_moving():
    pts = [np.zeros(2), np.array([0.5, 0.5]), np.array([1.0, 1.0])]
    traj = chain_joint_waypoints(pts, LIM)
    i = int(np.argmin(np.linalg.norm(traj.q_rad - pts[1], axis=1)))
    assert np.linalg.norm(traj.qd_rad_s[i]) > 0.2  # did not stop at the via point
    stop_and_go = (
        chain_joint_waypoints([pts[0], pts[1]], LIM).duration_s
        + chain_joint_waypoints([pts[1], pts[2]], LIM).duration_s
    )
    assert traj.duration_s < stop_and_go


def test_line_trajectory_is_min_jerk_between_endpoints():
    path = np.linspace([0.0, 0.0], [1.0, 2.0], 11)
    traj = line_trajectory(path, 1.0, dt_s=0.01)
    np.testing.assert_allclose(traj.q_rad[-1], [1.0, 2.0])
    assert abs(traj.qd_rad_s[0]).max() < 0.05 and abs(traj.qd_rad_s[-1]).max() < 0.05
    assert len(traj) == 100
