"""Run manifests: everything that decided a benchmark run or a batch, stored with it and named in its report.

A manifest records the code (git commit and whether the tree was dirty), package versions, the SHA-256 of every
task and init-state file used, the exact seeds (LIBERO-PRO: init-state indices) and their split, the planner
(model, temperature, endpoint name), the segmenter and whether it is privileged, cameras and resolution, the
memory regime (plan library off, or on with the hash of its contents), the executor, and per trial its verdict,
tokens, cost and latency. Its `id` is a hash of what defines the run (not of when it ran or what came out), so
a faithful re-run (`spark bench --from-manifest FILE`) has the same id on the same code and files.
"""

from __future__ import annotations

import functools
import hashlib
import json
import subprocess
from collections.abc import Sequence
from dataclasses import dataclass, replace
from datetime import UTC, datetime
from importlib import metadata
from pathlib import Path
from typing import Any

from ..trial import TrialConfig
from .run_file import read_rows, write_rows

VERSION = 1
REPO = Path(__file__).resolve().parents[2]
PACKAGES = (
    "spark-console",
    "mujoco",
    "robosuite",
    "libero",
    "bddl",
    "torch",
    "numpy",
    "transformers",
    "pin",
    "sqlalchemy",
    "ray",
    "google-genai",
    "openai",
)
PERCEPTION_RESOLUTION = "640x480"  # PerceptionResolver's render size (width x height, pixels)
_PER_RUN = ("task", "seed", "batch_id")  # TrialConfig fields that vary per trial, not per run


class ManifestError(ValueError):
    """A manifest file that cannot be read or re-run; the message names the file and the field."""


def sha256_file(path: Path) -> str:
    h = hashlib.sha256()
    with open(path, "rb") as f:
        for chunk in iter(lambda: f.read(1 << 20), b""):
            h.update(chunk)
    return h.hexdigest()


def git_state(root: Path = REPO) -> dict[str, Any]:
    """{commit, dirty} of the working tree (tracked files only); None for both outside a git checkout."""

    def git(*args: str) -> str | None:
        try:
            done = subprocess.run(["git", "-C", str(root), *args], capture_output=True, text=True, timeout=10)
        except (OSError, subprocess.TimeoutExpired):
            return None
        return done.stdout.strip() if done.returncode == 0 else None

    commit = git("rev-parse", "HEAD")
    status = git("status", "--porcelain", "--untracked-files=no") if commit else None
    return {"commit": commit, "dirty": None if status is None else bool(status)}


def package_versions() -> dict[str, str | None]:
    out: dict[str, str | None] = {}
    for name in PACKAGES:
        try:
            out[name] = metadata.version(name)
        except metadata.PackageNotFoundError:
            out[name] = None
    return out


def environment() -> dict[str, Any]:
    import platform

    from .report import machine

    return {
        "git": git_state(),
        "packages": package_versions(),
        "python": platform.python_version(),
        "machine": machine(),
    }


def task_files(tasks: list[str]) -> dict[str, str]:
    """{file: sha256} of every file that defines the tasks: LIBERO-PRO's BDDL and init-state files, else the
    module holding the task's definition and its reference plan. Paths are relative to the repository (or to the
    LIBERO-PRO data directory, prefixed `liberopro/`)."""
    import inspect

    from ..sim.tasks import TASKS

    files: dict[str, Path] = {}
    for name in tasks:
        if name.startswith("libero_"):
            from ..sim.libero_envs import data_dir
            from ..sim.libero_envs import tasks as libero_tasks

            task = next((t for t in libero_tasks() if t.name == name), None)
            if task is None:
                raise ManifestError(f"task {name!r}: no such LIBERO-PRO task under {data_dir()}")
            for path in (task.bddl, task.init_file):
                files["liberopro/" + str(path.relative_to(data_dir()))] = path
            continue
        spec = TASKS.get(name)
        if spec is None:
            raise ManifestError(f"task {name!r}: no such task")
        # the predicate's module; for robosuite suites also the module that builds and seeds the env
        for fn in (spec.success, spec.world_factory):
            while isinstance(fn, functools.partial):
                fn = fn.func
            try:
                source = inspect.getsourcefile(fn) if fn is not None else None
            except TypeError:  # a builtin or a callable object: no source file of its own
                source = None
            if source:
                files[_rel(Path(source))] = Path(source)
        plan = REPO / "spark_core" / "sim" / "tasks" / "reference" / f"{name}.yaml"
        if plan.is_file():
            files[_rel(plan)] = plan
    return {key: sha256_file(path) for key, path in sorted(files.items())}


def _rel(path: Path) -> str:
    path = path.resolve()
    return str(path.relative_to(REPO)) if path.is_relative_to(REPO) else str(path)


def memory_regime(library: Any = None, planner: str = "reference") -> dict[str, Any]:
    """The plan library the planner saw: off, or on with the number of plans and a hash of their contents at the
    start (a library also grows with the run's successes). Only LLM planners read it."""
    from ..catalog import PLANNERS

    if library is None or not getattr(library, "enabled", True):
        return {"plan_library": "off"}
    if PLANNERS[planner].offline:
        return {"plan_library": "off", "note": f"the {planner} planner reads no examples"}
    entries = [(e["instruction"], e["plan"]) for e in library.entries()]
    digest = hashlib.sha256(json.dumps(entries, sort_keys=True).encode()).hexdigest()
    return {"plan_library": "on", "path": str(getattr(library, "path", "")), "plans": len(entries), "sha256": digest}


def planner_record(config: TrialConfig) -> dict[str, Any]:
    from ..catalog import PLANNERS
    from ..planning.llm import LLMSettings

    entry = PLANNERS[config.planner]
    llm = not entry.offline
    return {
        "name": config.planner,
        "model": (config.model or entry.default_model) if llm else None,
        "temperature": LLMSettings(model="").temperature if llm else None,
        "endpoint": config.endpoint,
        "base_url": config.base_url,
        "given_plan": config.plan_text is not None,
    }


def segmenter_record(config: TrialConfig) -> dict[str, Any]:
    from ..catalog import SEGMENTERS

    seg = SEGMENTERS[config.segmenter]
    return {"name": config.segmenter, "privileged": seg.privileged, "description": seg.description}


def cameras_record(config: TrialConfig) -> dict[str, Any]:
    from ..catalog import SEGMENTERS

    if not SEGMENTERS[config.segmenter].cameras:
        return {"names": None, "resolution": None, "note": "no cameras: the segmenter reads simulator state"}
    names = list(config.cameras) if config.cameras else "the scene's perception cameras"
    return {"names": names, "resolution": PERCEPTION_RESOLUTION}


def config_record(config: TrialConfig) -> dict[str, Any]:
    from ..trial_record import config_record as record

    return {k: v for k, v in record(config).items() if k not in _PER_RUN}


def build(
    *,
    suite: str,
    tasks: list[str],
    seeds: Sequence[int],
    template: TrialConfig,
    split: str | None = None,
    executor: str = "local",
    workers: int = 1,
    ray_address: str | None = None,
    command: str = "",
    protocol: str | None = None,
    library: Any = None,
    batch_id: str | None = None,
) -> dict[str, Any]:
    """A run's manifest before it runs (`add_trials` completes it). Raises ManifestError for a task file missing."""
    seed_meaning = (
        "LIBERO-PRO init-state index" if suite == "liberopro" else "start-state seed (scene / robosuite sampler)"
    )
    run = {
        "suite": suite,
        "tasks": list(tasks),
        "seeds": list(seeds),
        "seed_meaning": seed_meaning,
        "split": split,
        "protocol": protocol,
        "config": config_record(template),
        "planner": planner_record(template),
        "segmenter": segmenter_record(template),
        "cameras": cameras_record(template),
        "memory": memory_regime(library, template.planner),
        "executor": {"name": executor, "workers": workers, "ray_address": ray_address},
    }
    env = environment()
    files = task_files(list(tasks))
    return {
        "manifest_version": VERSION,
        "id": _digest(run, env, files),
        "created_at": datetime.now(UTC).isoformat(timespec="seconds"),
        "command": command,
        "batch_id": batch_id,
        "run": run,
        "environment": env,
        "files": files,
        "trials": [],
    }


def measurement(suite: str, command: str = "") -> dict[str, Any]:
    """The manifest of a benchmark that runs no trial seeds (IK, speed, console latency, ...): what it ran on."""
    run = {"suite": suite, "kind": "measurement: no tasks or seeds"}
    env = environment()
    return {
        "manifest_version": VERSION,
        "id": _digest(run, env, {}),
        "created_at": datetime.now(UTC).isoformat(timespec="seconds"),
        "command": command,
        "run": run,
        "environment": env,
        "files": {},
    }


def _digest(run: dict, env: dict, files: dict) -> str:
    """What defines the run: its settings, the code and package versions, the task files (not where or when)."""
    key = {"run": run, "git": env["git"], "packages": env["packages"], "files": files}
    return hashlib.sha256(json.dumps(key, sort_keys=True, default=str).encode()).hexdigest()[:12]


def add_trials(manifest: dict[str, Any], rows: list[dict]) -> dict[str, Any]:
    """The manifest with each trial's outcome, tokens, cost and latency (wall seconds, and the planner's share)."""
    trials = [
        {
            "trial_id": r.get("trial_id"),
            "task": r["task"],
            "seed": r["seed"],
            "verdict": r["verdict"],
            "success": r["success"],
            "tokens": dict(r.get("usage") or {}),
            "cost_usd": r.get("cost_usd", 0.0),
            "wall_time_s": r.get("wall_time_s"),
            "planning_s": (r.get("phases_s") or {}).get("planning"),
        }
        for r in rows
    ]
    n = len(trials)
    totals = {
        "trials": n,
        "successes": sum(bool(t["success"]) for t in trials),
        "cost_usd": sum(t["cost_usd"] or 0.0 for t in trials),
        "tokens": _sum_tokens(t["tokens"] for t in trials),
        "wall_time_s": sum(t["wall_time_s"] or 0.0 for t in trials),
    }
    return {**manifest, "trials": trials, "totals": totals}


def _sum_tokens(usages) -> dict[str, int]:
    out: dict[str, int] = {}
    for u in usages:
        for k, v in u.items():
            if isinstance(v, int | float):
                out[k] = out.get(k, 0) + int(v)
    return out


def save(manifest: dict[str, Any], path: str | Path) -> None:
    """Write the manifest as JSON (gzipped when the name ends in .gz: run_file.py)."""
    if Path(path).suffix == ".gz":
        write_rows(path, manifest)
    else:
        Path(path).write_text(json.dumps(manifest, indent=1, default=str) + "\n")


def load(path: str | Path) -> dict[str, Any]:
    """Read and check a manifest file; ManifestError naming the file and what is wrong."""
    try:
        data = read_rows(path)
    except (OSError, EOFError) as e:  # gzip's errors among them
        raise ManifestError(f"manifest {path}: cannot read it ({getattr(e, 'strerror', None) or e})") from None
    except json.JSONDecodeError as e:
        raise ManifestError(f"manifest {path}: not JSON ({e})") from None
    if not isinstance(data, dict) or data.get("manifest_version") != VERSION:
        raise ManifestError(
            f"manifest {path}: manifest_version {data.get('manifest_version') if isinstance(data, dict) else None!r}, "
            f"this version reads {VERSION}"
        )
    for key in ("suite", "tasks", "seeds", "config", "executor"):
        if key not in data.get("run", {}):
            raise ManifestError(f"manifest {path}: run.{key} is missing")
    return data


@dataclass(frozen=True)
class Rerun:
    """What `spark bench --from-manifest` runs: the suite's tasks x seeds with the recorded settings."""

    suite: str
    tasks: list[str]
    seed: int
    trials: int
    template: TrialConfig
    split: str | None
    executor: str
    workers: int
    ray_address: str | None


def rerun(manifest: dict[str, Any]) -> Rerun:
    """The run a manifest describes, rebuilt; ManifestError if it cannot be run as recorded here."""
    from ..trial import TrialConfigError
    from ..trial_record import config_from_record
    from .executors import EXECUTORS

    run = manifest["run"]
    if run.get("per_trial_config"):
        raise ManifestError("run.per_trial_config: a batch whose trials differ in settings is not one bench run")
    seeds = [int(s) for s in run["seeds"]]
    if not seeds or seeds != list(range(seeds[0], seeds[0] + len(seeds))):
        raise ManifestError(f"run.seeds: expected consecutive seeds, got {seeds[:5]}...")
    if not run["tasks"]:
        raise ManifestError("run.tasks is empty")
    try:  # checked against the first task (the template's own task is replaced per trial)
        template = config_from_record({**run["config"], "task": run["tasks"][0], "seed": seeds[0]})
    except TrialConfigError as e:
        raise ManifestError(f"run.config: {e}") from None
    ex = run["executor"]
    if ex.get("name") not in EXECUTORS:  # a console batch: its trials ran in the console's workers
        ex = {"name": "local", "workers": 1}
    return Rerun(
        suite=run["suite"],
        tasks=list(run["tasks"]),
        seed=seeds[0],
        trials=len(seeds),
        template=replace(template, task="", seed=0),
        split=run.get("split"),
        executor=ex.get("name", "local"),
        workers=int(ex.get("workers", 1)),
        ray_address=ex.get("ray_address"),
    )


def drift(recorded: dict[str, Any], current: dict[str, Any]) -> list[str]:
    """How the code, packages and task files of `current` differ from `recorded` (empty: none)."""
    out = []
    old_git, new_git = recorded["environment"]["git"], current["environment"]["git"]
    if old_git["commit"] != new_git["commit"]:
        out.append(f"git commit {old_git['commit']} -> {new_git['commit']}")
    if new_git.get("dirty"):
        out.append("the working tree has uncommitted changes")
    old_p, new_p = recorded["environment"]["packages"], current["environment"]["packages"]
    changed = sorted(k for k in set(old_p) | set(new_p) if old_p.get(k) != new_p.get(k))
    out += [f"{k} {old_p.get(k)} -> {new_p.get(k)}" for k in changed]
    old_f, new_f = recorded.get("files", {}), current.get("files", {})
    out += [f"file {k} changed" for k in sorted(set(old_f) | set(new_f)) if old_f.get(k) != new_f.get(k)]
    old_m = recorded.get("run", {}).get("memory", {})
    new_m = current.get("run", {}).get("memory", {})
    if old_m.get("sha256") != new_m.get("sha256"):
        out.append(f"plan library {old_m.get('sha256', 'off')} -> {new_m.get('sha256', 'off')}")
    return out


def compare_verdicts(recorded: dict[str, Any], rows: list[dict]) -> list[str]:
    """(task, seed) whose verdict differs from the recorded one, in words (empty: all the same)."""
    before = {(t["task"], t["seed"]): t["verdict"] for t in recorded.get("trials", [])}
    return [
        f"{r['task']} seed {r['seed']}: {before.get((r['task'], r['seed']))} -> {r['verdict']}"
        for r in rows
        if before.get((r["task"], r["seed"])) != r["verdict"]
    ]


def summary(manifest: dict[str, Any]) -> str:
    """The manifest in a few lines, for a report's console output."""
    run, env = manifest["run"], manifest["environment"]
    git = env["git"]
    pk = env["packages"]
    versions = ", ".join(f"{k} {v}" for k, v in pk.items() if v and k in ("mujoco", "robosuite", "libero", "torch"))
    seeds = run["seeds"]
    planner, seg = run["planner"], run["segmenter"]
    llm = f" ({planner['model']}, temperature {planner['temperature']})" if planner["model"] else ""
    lines = [
        f"manifest {manifest['id']}: commit {(git['commit'] or 'unknown')[:12]}{' (dirty)' if git['dirty'] else ''}",
        f"  {versions}",
        f"  {len(run['tasks'])} task(s) x seeds {seeds[0]}-{seeds[-1]} ({run['seed_meaning']}; "
        f"split {run['split'] or 'none'}), {len(manifest['files'])} task files hashed",
        f"  planner {planner['name']}{llm}; segmenter {seg['name']} "
        f"({'PRIVILEGED' if seg['privileged'] else 'non-privileged'}); plan library {run['memory']['plan_library']}",
    ]
    if "totals" in manifest:
        t = manifest["totals"]
        lines.append(
            f"  {t['successes']}/{t['trials']} succeeded, ${t['cost_usd']:.4f}, tokens {t['tokens'] or 0}, "
            f"{t['wall_time_s']:.1f} trial-seconds"
        )
    return "\n".join(lines)


def batch_manifest(suite: str, configs: list[TrialConfig], batch_id: str, library: Any = None) -> dict[str, Any]:
    """The manifest of a console batch (explicit specs may differ per trial: each trial's settings are kept);
    `library`: the plan library its trials use."""
    tasks = list(dict.fromkeys(c.task for c in configs))
    m = build(
        suite=suite,
        tasks=tasks,
        seeds=sorted({c.seed for c in configs}),
        template=configs[0],
        executor="console",
        batch_id=batch_id,
        library=library,
        protocol=configs[0].eval_protocol,
    )
    if any(config_record(c) != m["run"]["config"] for c in configs):
        m["run"]["per_trial_config"] = [{"task": c.task, "seed": c.seed, "config": config_record(c)} for c in configs]
    m["run"]["seeds_per_task"] = {t: sorted({c.seed for c in configs if c.task == t}) for t in tasks}
    m["id"] = _digest(m["run"], m["environment"], m["files"])
    return m


__all__ = [
    "ManifestError",
    "Rerun",
    "add_trials",
    "batch_manifest",
    "build",
    "compare_verdicts",
    "drift",
    "environment",
    "load",
    "rerun",
    "save",
    "summary",
    "task_files",
]
