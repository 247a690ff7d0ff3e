"""The one catalog of what a trial can be made of: planners, segmenters (each with its `privileged` flag),
embodiments, suites and tasks, plus the closed sets the API and UI interpret (verdicts, node statuses, event
kinds). The CLI's choices, the API's validation, `GET /api/catalog` and the browser UI all read it; nothing
lists these names by hand anywhere else."""

from __future__ import annotations

from dataclasses import asdict, dataclass
from typing import Any


@dataclass(frozen=True)
class PlannerEntry:
    name: str
    description: str
    offline: bool  # runs with no network and no key
    needs_model: bool = False  # the caller must name a model
    default_model: str | None = None
    # False: it does not read the trial's instruction (the task's hand-written plan runs whatever it says), so the
    # API refuses one that differs from the task's own and the UI's field is off
    reads_instruction: bool = True


@dataclass(frozen=True)
class SegmenterEntry:
    """A perception backend. `privileged` entries read simulator state (renderer ids, object names or poses):
    every figure they produce says so. `cameras` is False for the source that skips cameras altogether."""

    name: str
    description: str
    privileged: bool
    cameras: bool = True
    needs: str = ""  # what must be on this machine (a checkpoint), in words


@dataclass(frozen=True)
class EmbodimentEntry:
    """A robot set-up and the arm names a plan may tag its nodes with on it. `suite`: the benchmark suite whose own
    env brings this robot (it runs that suite's tasks and nothing else); None for a set-up our scene builder puts
    any task that fits on."""

    name: str
    description: str
    arms: tuple[str, ...]
    suite: str | None = None


PLANNERS: dict[str, PlannerEntry] = {
    p.name: p
    for p in (
        PlannerEntry(
            "reference",
            "the task's hand-written reference plan (no planner call)",
            offline=True,
            reads_instruction=False,
        ),
        PlannerEntry(
            "rules",
            "offline rules planner: parses the instruction, grounds its phrases in what perception found",
            offline=True,
        ),
        PlannerEntry(
            "gemini",
            "Google Gemini through google-genai (GEMINI_API_KEY)",
            offline=False,
            default_model="gemini-3.1-pro-preview",
        ),
        PlannerEntry("openai", "any OpenAI-compatible chat server (OPENAI_API_KEY)", offline=False, needs_model=True),
    )
}

# What a trial perceives with when nobody chose: the camera-only segmenter (issue 17's bar met), not the oracle. The
# console's form, the API, the CLI and the benchmarks all start from it.
DEFAULT_SEGMENTER = "learned"

SEGMENTERS: dict[str, SegmenterEntry] = {
    s.name: s
    for s in (
        SegmenterEntry(
            "sim",
            "ORACLE masks from the renderer's object ids; prompts grounded against the simulator's object names",
            privileged=True,
        ),
        SegmenterEntry(
            "sim-noisy",
            "the sim oracle with a seeded failure model (misses, erosion, confusion, depth noise)",
            privileged=True,
        ),
        SegmenterEntry(
            "learned",
            "camera-only: a compact RGB-D network trained here on our own renders (per-pixel category, colour, "
            "instance boundaries); prompts grounded against its category names and descriptions",
            privileged=False,
        ),
        SegmenterEntry(
            "sam3",
            "SAM3 (transformers Sam3Model) on RGB; depth and camera parameters lift masks to 3D",
            privileged=False,
            needs="a SAM3 checkpoint directory (SPARK_SAM3_MODEL)",
        ),
        SegmenterEntry(
            "privileged-keypoints",
            "ground-truth keypoints from simulator state: no cameras, no segmentation (measures control alone)",
            privileged=True,
            cameras=False,
        ),
    )
}

# The robot set-ups our scene builder builds a task's scene with (sim/embodiments.py): what `spark run --embodiment`
# offers and `spark bench embodiments` compares the builtin tasks on.
EMBODIMENTS: dict[str, EmbodimentEntry] = {
    e.name: e
    for e in (
        EmbodimentEntry("panda", "one Franka Panda", ("right",)),
        EmbodimentEntry("ur10", "one UR10 with a Robotiq-2F-85-like gripper", ("right",)),
        EmbodimentEntry("bimanual", "two Pandas 0.6 m apart over one table", ("left", "right")),
    )
}

# The robots a benchmark's own env comes with: each runs its suite's tasks only (the names those tasks list as their
# embodiments), never a builtin scene. Listed for their arms, which a submitted plan's arm tags are checked against,
# as RobosuiteWorld names them: robot 0 is `right`, robot 1 `left` (tests/sim/test_embodiment_catalog.py holds
# these to the envs' robots).
BENCHMARK_EMBODIMENTS: dict[str, EmbodimentEntry] = {
    e.name: e
    for e in (
        EmbodimentEntry("robosuite-panda", "robosuite's one Panda (CaP-Bench one-arm envs)", ("right",), "capbench"),
        EmbodimentEntry(
            "robosuite-two-pandas",
            "robosuite's two Pandas facing each other across the table (CaP-Bench TwoArm envs)",
            ("right", "left"),
            "capbench",
        ),
        EmbodimentEntry("libero-panda", "LIBERO's one mounted Panda (LIBERO-PRO envs)", ("right",), "liberopro"),
    )
}

# Every embodiment a task can name: what the API validates and GET /api/catalog lists
ALL_EMBODIMENTS: dict[str, EmbodimentEntry] = {**EMBODIMENTS, **BENCHMARK_EMBODIMENTS}


class CatalogError(ValueError):
    """A name that is not in the catalog; the message lists what is."""


def _check(kind: str, name: str, names: Any) -> str:
    if name not in names:
        raise CatalogError(f"unknown {kind} {name!r}; available: {', '.join(names)}")
    return name


def check_planner(name: str) -> str:
    return _check("planner", name, PLANNERS)


def check_segmenter(name: str) -> str:
    return _check("segmenter", name, SEGMENTERS)


def check_embodiment(name: str) -> str:
    return _check("embodiment", name, ALL_EMBODIMENTS)


def suites() -> dict[str, list[str]]:
    """suite -> task names (imports the simulator lazily: the grammar-only CLI stays fast)."""
    from .sim.tasks import SUITES

    return {suite: list(tasks) for suite, tasks in SUITES.items()}


def check_task(name: str):
    """The TaskSpec named `name`."""
    from .sim.tasks import TASKS

    _check("task", name, TASKS)
    return TASKS[name]


def task_entry(name: str) -> dict[str, Any]:
    """What the console shows about a task: suite, instruction, success condition, embodiments, reference plan."""
    task = check_task(name)
    suite = next(s for s, names in suites().items() if name in names)
    return {
        "name": name,
        "suite": suite,
        "instruction": task.instruction,
        "predicate": task.predicate,
        "embodiments": list(task.embodiments),
        "has_reference_plan": task.has_reference_plan,
        "max_sim_s": task.max_sim_s,
        "tags": list(task.tags),
        "objects": [o.label for o in task.objects],
    }


def enums() -> dict[str, Any]:
    """The closed sets the API schema and the UI interpret, and what each event kind makes of its node's status
    (`paused` is shown, not a life-cycle state; `retrying` leaves the status as it is)."""
    from .execution import EventKind, NodeStatus, TreeStatus
    from .trial_outcome import Verdict

    event_status = {
        EventKind.STARTED: NodeStatus.RUNNING.value,
        EventKind.SUCCEEDED: NodeStatus.SUCCEEDED.value,
        EventKind.FAILED: NodeStatus.FAILED.value,
        EventKind.PAUSED: "paused",
    }
    return {
        "verdict": [v.value for v in Verdict],
        "node_status": [s.value for s in NodeStatus],
        "event_kind": [k.value for k in EventKind],
        "tree_status": [s.value for s in TreeStatus],
        "event_node_status": {k.value: v for k, v in event_status.items()},
    }


def catalog_json(with_tasks: bool = True) -> dict[str, Any]:
    """Everything above as plain JSON (for `GET /api/catalog` and `spark catalog`), with the LLM endpoints the
    operator configured (names, planners and models only)."""
    out: dict[str, Any] = {
        "planners": [asdict(p) for p in PLANNERS.values()],
        "segmenters": [asdict(s) for s in SEGMENTERS.values()],
        "default_segmenter": DEFAULT_SEGMENTER,
        "embodiments": [asdict(e) for e in ALL_EMBODIMENTS.values()],
        "suites": suites(),
        **enums(),
    }
    from .bench.protocols import protocols_json
    from .planning.endpoints import configured_endpoints

    out["protocols"] = protocols_json()  # the paper's evaluation configurations (spark bench --protocol)
    out["endpoints"] = [e.public() for e in configured_endpoints().values()]
    if with_tasks:
        out["tasks"] = [task_entry(t) for names in out["suites"].values() for t in names]
    return out


__all__ = [
    "ALL_EMBODIMENTS",
    "BENCHMARK_EMBODIMENTS",
    "CatalogError",
    "DEFAULT_SEGMENTER",
    "EMBODIMENTS",
    "EmbodimentEntry",
    "PLANNERS",
    "PlannerEntry",
    "SEGMENTERS",
    "SegmenterEntry",
    "catalog_json",
    "check_embodiment",
    "check_planner",
    "check_segmenter",
    "check_task",
    "enums",
    "suites",
    "task_entry",
]
