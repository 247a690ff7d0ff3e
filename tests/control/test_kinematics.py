"""pinocchio and MuJoCo agree on the Panda (same URDF); IK solves reachable targets and names unreachable ones."""

import numpy as np
import pytest

from spark_core.control import ArmKinematics, Pose, Unreachable, solve_ik, top_down_rotation
from spark_core.control.panda import panda
from spark_core.sim.scene import build_scene
from spark_core.sim.world import MujocoWorld


@pytest.fixture(scope="module")
def world():
    w = MujocoWorld(build_scene({"right": (panda(), np.eye(4))}, [], seed=0))
    yield w
    w.close()


def test_fk_matches_mujoco_site(world):
    kin = world.kinematics["right"]
    rng = np.random.default_rng(1)
    adr = world._qadr["right"]
    for _ in range(20):
        q = rng.uniform(kin.lower, kin.upper)
        world.data.qpos[adr] = q
        import mujoco

        mujoco.mj_forward(world.model, world.data)
        fk = kin.fk(q)
        mj = world.tcp_pose("right")
        np.testing.assert_allclose(fk.position_m, mj.position_m, atol=1e-6)
        np.testing.assert_allclose(fk.rotation, mj.rotation, atol=1e-6)


def test_home_points_down():
    kin = ArmKinematics(panda())
    np.testing.assert_allclose(kin.fk(panda().home_q_rad).rotation, top_down_rotation(0.0), atol=1e-5)


def test_ik_reaches_random_targets_within_limits():
    robot = panda()
    kin = ArmKinematics(robot)
    rng = np.random.default_rng(7)
    for _ in range(25):
        target = kin.fk(rng.uniform(kin.lower + 0.05, kin.upper - 0.05))
        if target.position_m[2] < 0 or np.linalg.norm(target.position_m[:2]) < 0.15:
            continue
        res = solve_ik(kin, target, robot.home_q_rad, rng=rng)
        assert kin.within_limits(res.q)
        got = kin.fk(res.q)
        assert np.linalg.norm(got.position_m - target.position_m) < 1e-3


def test_unreachable_target_names_the_target():
    kin = ArmKinematics(panda())
    with pytest.raises(Unreachable, match=r"for grasp pose at \(2\.000, 0\.000, 0\.300\) m") as info:
        solve_ik(
            kin, Pose(np.array([2.0, 0.0, 0.3]), top_down_rotation()), panda().home_q_rad, restarts=2, what="grasp pose"
        )
    assert "closest" in str(info.value)
