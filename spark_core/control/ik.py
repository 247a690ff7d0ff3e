"""Damped-least-squares inverse kinematics with restarts (pinocchio)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pinocchio as pin

from .kinematics import ArmKinematics
from .pose import Pose


class Unreachable(Exception):
    """No joint configuration within limits reaches the target. The message names the target."""


@dataclass(frozen=True)
class IKResult:
    q: np.ndarray
    position_error_m: float
    rotation_error_rad: float
    iterations: int
    restarts: int


def solve_ik(
    kin: ArmKinematics,
    target: Pose | np.ndarray,
    q_seed: np.ndarray,
    *,
    restarts: int = 10,
    max_iter: int = 150,
    tol_m: float = 1e-4,
    tol_rad: float = 1e-3,
    damping: float = 1e-2,
    rng: np.random.Generator | None = None,
    what: str = "target",
) -> IKResult:
    """Joint angles putting the TCP at `target` (a Pose, or a bare position for position-only IK).

    Tries the seed first, then perturbed seeds, then uniform random configurations. Raises Unreachable.
    """
    rng = rng or np.random.default_rng(0)
    if isinstance(target, Pose):
        p_target, R_target = np.asarray(target.position_m, float), target.rotation
    else:
        p_target, R_target = np.asarray(target, float), None
    lo, hi = kin.lower, kin.upper
    best: tuple[float, tuple[float, float] | None] = (np.inf, None)
    total_iter = 0
    for attempt in range(restarts + 1):
        if attempt == 0:
            q = np.clip(np.asarray(q_seed, float), lo, hi)
        elif attempt <= 2:
            q = np.clip(q_seed + rng.normal(0.0, 0.3 * attempt, kin.nq), lo, hi)
        else:
            q = rng.uniform(lo, hi)
        for _it in range(max_iter):
            total_iter += 1
            T = kin._tcp_se3(q)
            e_pos = p_target - T.translation
            if R_target is not None:
                e_rot = T.rotation @ pin.log3(T.rotation.T @ R_target)
                err = np.concatenate([e_pos, e_rot])
                J = kin.jacobian(q)
            else:
                e_rot = np.zeros(3)
                err = e_pos
                J = kin.jacobian(q)[:3]
            pe, re = float(np.linalg.norm(e_pos)), float(np.linalg.norm(e_rot))
            if pe < tol_m and re < tol_rad:
                return IKResult(q, pe, re, total_iter, attempt)
            if pe + 0.1 * re < best[0]:
                best = (pe + 0.1 * re, (pe, re))
            # Damping shrinks near the solution (fast Gauss-Newton convergence) and is full far from it (stable).
            lam2 = damping**2 * min(1.0, 10.0 * (pe + 0.1 * re)) + 1e-8
            dq = J.T @ np.linalg.solve(J @ J.T + lam2 * np.eye(J.shape[0]), err)
            # Active set: joints pinned at a limit and pushed further drop out, the others take up the motion.
            pinned = ((q <= lo + 1e-9) & (dq < 0)) | ((q >= hi - 1e-9) & (dq > 0))
            if pinned.any():
                J = J * ~pinned
                dq = J.T @ np.linalg.solve(J @ J.T + lam2 * np.eye(J.shape[0]), err)
            step = np.linalg.norm(dq)
            if step > 0.5:
                dq *= 0.5 / step
            q = np.clip(q + dq, lo, hi)
    pe, re = best[1] if best[1] else (np.inf, np.inf)
    where = "(" + ", ".join(f"{x:.3f}" for x in p_target) + ")"
    raise Unreachable(
        f"IK found no joint configuration within limits for {what} at {where} m (world) after {restarts} restarts; "
        f"closest: {pe * 100:.1f} cm, {np.degrees(re):.1f} deg off"
    )
