"""Joint trajectories: ruckig time-optimal jerk-limited segments chained through via points, and min-jerk
time scaling of dense straight-line Cartesian paths.

ruckig's `intermediate_positions` calls a cloud API (fails offline), so waypoints are chained here: each segment
ends at its via point with a velocity that keeps the motion moving instead of stopping at every waypoint.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from ruckig import InputParameter, Result, Ruckig, Trajectory


@dataclass(frozen=True)
class JointTrajectory:
    """Samples at a fixed control period. times_s (N,), q_rad (N, dof), qd_rad_s (N, dof)."""

    times_s: np.ndarray
    q_rad: np.ndarray
    qd_rad_s: np.ndarray

    @property
    def duration_s(self) -> float:
        return float(self.times_s[-1]) if len(self.times_s) else 0.0

    def __len__(self) -> int:
        return len(self.times_s)


@dataclass(frozen=True)
class Limits:
    velocity: np.ndarray  # rad/s per joint
    acceleration: np.ndarray  # rad/s^2
    jerk: np.ndarray  # rad/s^3

    def scaled(self, factor: float) -> Limits:
        return Limits(self.velocity * factor, self.acceleration * factor, self.jerk * factor)


def _segment(q0, v0, a0, q1, v1, lim: Limits) -> Trajectory | None:
    dof = len(q0)
    otg = Ruckig(dof)
    inp = InputParameter(dof)
    inp.current_position, inp.current_velocity, inp.current_acceleration = list(q0), list(v0), list(a0)
    inp.target_position, inp.target_velocity, inp.target_acceleration = list(q1), list(v1), [0.0] * dof
    inp.max_velocity, inp.max_acceleration, inp.max_jerk = list(lim.velocity), list(lim.acceleration), list(lim.jerk)
    traj = Trajectory(dof)
    res = otg.calculate(inp, traj)
    return traj if res in (Result.Working, Result.Finished) else None


def _via_velocities(points: list[np.ndarray], lim: Limits) -> list[np.ndarray]:
    """Per-joint velocity at each via point: the mean of neighbouring segment speeds where the joint keeps its
    direction, zero where it reverses (and at both ends)."""
    n = len(points)
    vs = [np.zeros_like(points[0]) for _ in range(n)]
    seg_t = [max(float(np.max(np.abs(points[i + 1] - points[i]) / (0.5 * lim.velocity))), 0.05) for i in range(n - 1)]
    for i in range(1, n - 1):
        d0, d1 = points[i] - points[i - 1], points[i + 1] - points[i]
        same = np.sign(d0) * np.sign(d1) > 0
        v = 0.5 * (d0 / seg_t[i - 1] + d1 / seg_t[i])
        vs[i] = np.where(same, np.clip(v, -0.5 * lim.velocity, 0.5 * lim.velocity), 0.0)
    return vs


def chain_joint_waypoints(
    waypoints: list[np.ndarray], lim: Limits, dt_s: float = 0.01, q0_velocity: np.ndarray | None = None
) -> JointTrajectory:
    """One smooth trajectory through joint waypoints (the first is the current configuration)."""
    points = [np.asarray(w, float) for w in waypoints]
    vias = _via_velocities(points, lim)
    if q0_velocity is not None:
        vias[0] = np.asarray(q0_velocity, float)
    segs: list[Trajectory] = []
    v, a = vias[0], np.zeros_like(points[0])
    for i in range(1, len(points)):
        traj = _segment(points[i - 1], v, a, points[i], vias[i], lim)
        if traj is None:  # a via velocity that cannot be reached in this segment: stop there instead
            traj = _segment(points[i - 1], v, a, points[i], np.zeros_like(v), lim)
            if traj is None:
                raise ValueError(f"ruckig could not plan segment {i} of {len(points) - 1}")
        segs.append(traj)
        p, v, a = (np.asarray(x) for x in traj.at_time(traj.duration))
    total = sum(s.duration for s in segs)
    n = max(int(np.ceil(total / dt_s)), 1)
    times = np.arange(1, n + 1) * dt_s
    times[-1] = max(times[-1], total)
    qs, qds = [], []
    starts = np.cumsum([0.0] + [s.duration for s in segs])
    for t in times:
        k = min(int(np.searchsorted(starts, t, side="right") - 1), len(segs) - 1)
        pos, vel, _ = segs[k].at_time(min(t - starts[k], segs[k].duration))
        qs.append(pos)
        qds.append(vel)
    return JointTrajectory(times, np.asarray(qs), np.asarray(qds))


def min_jerk(s: np.ndarray) -> np.ndarray:
    return 10 * s**3 - 15 * s**4 + 6 * s**5


def line_trajectory(q_path: np.ndarray, duration_s: float, dt_s: float = 0.01) -> JointTrajectory:
    """Time-scale a dense joint path (IK of evenly spaced points on a straight Cartesian line) with a
    min-jerk profile: the TCP moves along the line, starting and stopping smoothly."""
    q_path = np.asarray(q_path, float)
    n = max(int(np.ceil(duration_s / dt_s)), 1)
    times = np.arange(1, n + 1) * dt_s
    s = min_jerk(np.clip(times / duration_s, 0.0, 1.0)) * (len(q_path) - 1)
    idx = np.minimum(s.astype(int), len(q_path) - 2) if len(q_path) > 1 else np.zeros(n, int)
    frac = (s - idx)[:, None]
    if len(q_path) == 1:
        q = np.repeat(q_path, n, axis=0)
    else:
        q = q_path[idx] * (1 - frac) + q_path[idx + 1] * frac
    qd = np.gradient(q, dt_s, axis=0) if n > 1 else np.zeros_like(q)
    return JointTrajectory(times, q, qd)
