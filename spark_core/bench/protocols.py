"""The paper's evaluation configurations as named protocols for `spark bench` and batches.

- `fair`: the task language only; the prompt-synthesis call names the objects, one prompt each.
- `bddl`: `fair` plus LIBERO's canonical object names (the object categories of the task's BDDL file, e.g.
  `akita_black_bowl` -> "akita black bowl"; categories only: no instance ids, no poses) for perception to look for.
- `adaptive`: `fair` plus three alternative colour-and-shape prompts per object from the synthesis call, the
  single confident detection kept.
- `s2`: CaP-Bench under CaP-X's S2 rules: vision only (camera perception, no ground-truth lookup), the planner
  writes the plan (no reference plans).

Every protocol runs perception through cameras with a non-privileged segmenter: a figure measured with a
privileged source (the sim oracles, ground-truth keypoints) can never be reported under these names.
"""

from __future__ import annotations

import re
from dataclasses import asdict, dataclass, replace
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from ..trial import TrialConfig

LIBERO_CAMERAS = ("agentview", "robot0_eye_in_hand")  # the paper's LIBERO-PRO cameras, 640x480 each
IMAGE_SIZE_PX = (640, 480)


class ProtocolError(ValueError):
    """A trial or bench that cannot be reported under the named protocol; the message says why."""


@dataclass(frozen=True)
class Protocol:
    name: str
    description: str
    suites: tuple[str, ...]  # the suites the configuration is defined on
    wording: str  # what the planner and perception are given besides the scene
    adaptive: bool  # three alternative prompts per object
    bddl_names: bool  # LIBERO's canonical object names added to what perception looks for
    cameras: tuple[str, ...] | None  # None: the scene's own perception cameras


PROTOCOLS: dict[str, Protocol] = {
    p.name: p
    for p in (
        Protocol(
            "fair",
            "the paper's fair configuration: the task language only; the prompt-synthesis call names the objects "
            "to detect, one prompt each",
            ("liberopro",),
            "task language only",
            adaptive=False,
            bddl_names=False,
            cameras=LIBERO_CAMERAS,
        ),
        Protocol(
            "bddl",
            "the fair configuration plus LIBERO's canonical object names (the BDDL file's object categories) for "
            "perception to look for",
            ("liberopro",),
            "task language + LIBERO's canonical object names (BDDL categories; no ids, no poses)",
            adaptive=False,
            bddl_names=True,
            cameras=LIBERO_CAMERAS,
        ),
        Protocol(
            "adaptive",
            "the fair configuration plus three alternative colour-and-shape prompts per object from the "
            "prompt-synthesis call; the single confident detection is kept",
            ("liberopro",),
            "task language only",
            adaptive=True,
            bddl_names=False,
            cameras=LIBERO_CAMERAS,
        ),
        Protocol(
            "s2",
            "CaP-Bench under CaP-X's S2 rules: vision only (camera perception, no ground-truth lookup); the "
            "planner writes the plan",
            ("capbench",),
            "task language only",
            adaptive=True,
            bddl_names=False,
            cameras=None,
        ),
    )
}


def check_protocol(name: str) -> Protocol:
    if name not in PROTOCOLS:
        raise ProtocolError(f"unknown protocol {name!r}; available: {', '.join(PROTOCOLS)}")
    return PROTOCOLS[name]


def suite_of(task: str) -> str | None:
    from ..sim.tasks import SUITES

    return next((s for s, tasks in SUITES.items() if task in tasks), None)


def check_config(config: TrialConfig) -> Protocol:
    """Raise ProtocolError unless `config` may be reported under its protocol: a non-privileged segmenter
    through cameras, a planner that writes the plan, a task of the protocol's suites, the protocol's prompts."""
    from ..catalog import SEGMENTERS

    p = check_protocol(str(config.eval_protocol))
    seg = SEGMENTERS[config.segmenter]
    if seg.privileged:
        raise ProtocolError(
            f"segmenter: {config.segmenter!r} is privileged ({seg.description}); protocol {p.name!r} is vision "
            "only: use a non-privileged segmenter (`spark catalog` lists them, e.g. sam3)"
        )
    if config.plan_text is not None or config.planner == "reference":
        raise ProtocolError(f"planner: under protocol {p.name!r} a planner writes the plan (not a given plan)")
    suite = suite_of(config.task) if config.task else None
    if suite is not None and suite not in p.suites:
        raise ProtocolError(f"task: protocol {p.name!r} is defined on {', '.join(p.suites)}, not {suite}")
    if config.adaptive != p.adaptive:
        raise ProtocolError(f"adaptive: protocol {p.name!r} runs with adaptive prompts {'on' if p.adaptive else 'off'}")
    if p.cameras is not None and config.cameras not in (None, p.cameras):
        raise ProtocolError(f"cameras: protocol {p.name!r} uses {' + '.join(p.cameras)}")
    return p


def apply(name: str, config: TrialConfig) -> TrialConfig:
    """`config` with the protocol's settings (name, adaptive prompts, cameras), checked."""
    p = check_protocol(name)
    out = replace(config, eval_protocol=p.name, adaptive=p.adaptive, cameras=p.cameras or config.cameras)
    check_config(out)
    return out


def apply_protocol(name: str, config: TrialConfig) -> TrialConfig:
    """`apply` under the name the engine's public API exports (the console's trial and batch requests)."""
    return apply(name, config)


def bddl_object_names(task: str) -> list[str]:
    """LIBERO's canonical object names for a LIBERO-PRO task: the categories of its BDDL `(:objects ...)` (the
    objects it manipulates, not the fixtures), as phrases (`akita_black_bowl` -> "akita black bowl")."""
    from ..sim.libero_envs import tasks

    found = next((t for t in tasks() if t.name == task), None)
    if found is None:
        return []
    m = re.search(r"\(:objects(.*?)\)", found.bddl.read_text(), re.S)
    categories = re.findall(r"-\s*([A-Za-z0-9_]+)", m.group(1)) if m else []
    return list(dict.fromkeys(c.replace("_", " ") for c in categories))


def describe(name: str) -> str:
    """The protocol line's opening: its name and what it gives, and that these smoke figures are not the
    paper's (no SAM3 weights here)."""
    p = check_protocol(name)
    return (
        f"protocol `{p.name}`: {p.description}; wording: {p.wording}; cameras "
        + ("+".join(p.cameras) if p.cameras else "the scene's")
        + f" {IMAGE_SIZE_PX[0]}x{IMAGE_SIZE_PX[1]}"
    )


def protocols_json() -> list[dict[str, Any]]:
    """The table as plain JSON (tuples as lists), for the catalog."""
    return [{k: list(v) if isinstance(v, tuple) else v for k, v in asdict(p).items()} for p in PROTOCOLS.values()]
