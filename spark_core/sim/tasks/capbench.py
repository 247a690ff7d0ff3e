"""The `capbench` suite: CaP-Bench robosuite tasks (as CaP-X defines them) behind the robosuite adapter.

Success is robosuite's own predicate on the env (plus what CaP-X adds, said in `predicate`), evaluated after the
plan ends; a trial also fails when it used more simulated time than the task's horizon (N steps at 20 Hz).
Needs the benchmark extras (`make bench-deps`).
"""

from __future__ import annotations

from functools import partial

from ..capbench_envs import ENVS, WIPE_MARKERS, WipeReferee, make_env
from ..robosuite_world import RobosuiteObject as Obj
from ..robosuite_world import RobosuiteWorld
from .spec import TaskSpec

ROBOSUITE_PANDA = "robosuite-panda"
ROBOSUITE_TWO_PANDAS = "robosuite-two-pandas"

# What perception can be asked about in each env: labels, descriptions, and the bodies (or geoms) they are.
OBJECTS: dict[str, list[Obj]] = {
    "Lift": [Obj("red cube", "small red wooden cube", "cube_main")],
    "Stack": [
        Obj("red cube", "small red wooden cube", "cubeA_main"),
        Obj("green cube", "green wooden cube", "cubeB_main"),
    ],
    "CubeRestack": [
        Obj("red cube", "small red wooden cube", "cubeA_main"),
        Obj("green cube", "small green wooden cube", "cubeB_main"),
    ],
    # the nut is its ring (whose centre is the opening's); the handle is a part of its own
    "NutAssemblySquare": [
        Obj(
            "square nut",
            "brass square nut",
            "SquareNut_main",
            geoms=("SquareNut_g0", "SquareNut_g1", "SquareNut_g2", "SquareNut_g3"),
            category="tool",
        ),
        Obj(
            "square nut handle",
            "handle of the brass square nut",
            "SquareNut_main",
            geoms=("SquareNut_g4",),
            category="tool",
        ),
        Obj("square peg", "square metal peg standing on the table", "peg1", category="fixture"),
        Obj("round peg", "round metal peg standing on the table", "peg2", category="fixture"),
    ],
    # the dirt is one region made of robosuite's 100 marker discs; a wiped disc turns transparent and is gone
    "Wipe": [
        Obj(
            "dirt",
            "brown dirt stains on the table",
            "table",
            geoms=tuple(f"contact{i}_g0_vis" for i in range(WIPE_MARKERS)),
            category="region",
        )
    ],
    "TwoArmLift": [
        Obj("pot", "metal pot with two handles", "pot_root", category="container"),
        Obj(
            "pot handle 0", "one handle of the pot", "pot_root", geoms=("pot_handle0_c",), category="container"
        ),  # the grip bar
        Obj("pot handle 1", "the other handle of the pot", "pot_root", geoms=("pot_handle1_c",), category="container"),
    ],
    "TwoArmHandover": [
        Obj("hammer", "hammer with a wooden handle", "hammer_root", category="tool"),
        Obj("hammer handle", "wooden handle of the hammer", "hammer_root", geoms=("hammer_handle",), category="tool"),
    ],
}


def _world(name: str, seed: int) -> RobosuiteWorld:
    world = RobosuiteWorld(make_env(name, seed), OBJECTS[name], seed=seed)
    if name == "Wipe":
        world.referee = WipeReferee(world.env)
        world.monitors.append(world.referee)
    return world


def _wipe_success(w: RobosuiteWorld) -> bool:
    return bool(w.env._check_success()) and not w.referee.ended


def _lift_success(w: RobosuiteWorld) -> bool:
    env = w.env
    return bool(env._check_success() and env._check_grasp(gripper=env.robots[0].gripper, object_geoms=env.cube))


def _robosuite_success(w: RobosuiteWorld) -> bool:
    return bool(w.env._check_success())


def _task(name: str, instruction: str, success, predicate: str) -> TaskSpec:
    """The env's robots decide the embodiment: one Panda or two (the catalog lists both with their arms)."""
    return TaskSpec(
        name,
        instruction,
        (),
        success,
        predicate,
        max_sim_s=ENVS[name].horizon_s,
        tags=("capbench", "robosuite"),
        embodiments=(ROBOSUITE_TWO_PANDAS if len(ENVS[name].robots) == 2 else ROBOSUITE_PANDA,),
        world_factory=partial(_world, name),
    )


SUITE: dict[str, TaskSpec] = {
    t.name: t
    for t in [
        _task(
            "Lift",
            "lift the red cube",
            _lift_success,
            "robosuite Lift: cube > 4 cm above the table, and (CaP-X) still grasped at the end",
        ),
        _task(
            "Stack",
            "stack the red cube on the green cube",
            _robosuite_success,
            "robosuite Stack: red cube lifted, touching the green cube, not grasped "
            "(CaP-X placement x +-18, y +-12 cm)",
        ),
        _task(
            "CubeRestack",
            "put the red cube on top of the green cube",
            _robosuite_success,
            "robosuite Stack predicate on CaP-X CubeRestack: two 4 cm cubes, green starts on red; "
            "red ends on green, released",
        ),
        _task(
            "Wipe",
            "wipe the dirt off the table",
            _wipe_success,
            "robosuite Wipe: all 100 markers wiped by robosuite's own check at 20 Hz (pad pressed flat on them), "
            "before any arm contact or joint-limit approach, which end robosuite's episode",
        ),
        _task(
            "NutAssemblySquare",
            "put the square nut onto the square peg",
            _robosuite_success,
            "robosuite NutAssemblySquare: nut within 3 cm of the peg axis, below 5 cm, gripper > 4.2 cm from the nut",
        ),
        _task(
            "TwoArmLift",
            "lift the pot with both arms, holding it by its two handles",
            _robosuite_success,
            "robosuite TwoArmLift: pot bottom > 10 cm above the table (does not check that both arms hold it)",
        ),
        _task(
            "TwoArmHandover",
            "pick up the hammer with one arm and hand it over to the other arm",
            _robosuite_success,
            "robosuite TwoArmHandover: arm 1 grasps the handle, arm 0 holds nothing, hammer above the height threshold",
        ),
    ]
}
