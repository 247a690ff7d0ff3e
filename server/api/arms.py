"""A given plan's arm tags checked against the embodiment that is to run it, when the trial is submitted (or the
plan validated for an embodiment). The executor refuses a node whose arm the robot lacks only when that node
runs: after the scene was built and every node before it had run, the trial ended `tree_failed` for a request
that could never have worked. The embodiment's arms come from the catalog, which lists every embodiment a task runs
on: our scene builder's set-ups and the robots the CaP-Bench and LIBERO-PRO envs come with."""

from __future__ import annotations

from typing import Any

from spark_core import ALL_EMBODIMENTS


def arm_errors(plan: Any, embodiment: str) -> list[tuple[str, str]]:
    """(path, message) for each arm tag of `plan` (a grammar Plan) that `embodiment` has no arm for, at the node
    whose tag says so (its children inherit it: named once), and for each two-arm primitive on a one-arm robot.
    [] when the plan fits, or when the catalog does not list the embodiment (no task runs on one it does not list:
    tests/sim/test_embodiment_catalog.py; the executor would still check)."""
    entry = ALL_EMBODIMENTS.get(embodiment)
    if entry is None:
        return []
    arms = tuple(entry.arms)
    effective: dict[str, str | None] = {}
    out: list[tuple[str, str]] = []
    for path, node, arm in plan.nodes():
        effective[path] = arm
        parent = path.rsplit(".children[", 1)[0] if ".children[" in path else None
        inherited = effective.get(parent) if parent is not None else None
        if node.arm is not None and node.arm not in arms and inherited is None:
            out.append(
                (
                    f"{path}.arm",
                    f"arm {node.arm!r}: the {embodiment} embodiment has no such arm; its arms: {', '.join(arms)}",
                )
            )
        elif getattr(node, "primitive", None) is not None and node.spec.uses_both_arms and len(arms) < 2:
            out.append(
                (path, f"{node.primitive} uses two arms: the {embodiment} embodiment has one ({', '.join(arms)})")
            )
    return out


def arm_problem(plan: Any, embodiment: str, task: str, default: bool) -> str | None:
    """The arm errors as one 422 message (naming the embodiment's arms, and which of the task's embodiments have
    the arms the plan uses), or None."""
    errors = arm_errors(plan, embodiment)
    if not errors:
        return None
    from spark_core import check_task

    used = {arm for _path, _node, arm in plan.nodes() if arm is not None}
    two = any(getattr(n, "primitive", None) is not None and n.spec.uses_both_arms for _p, n, _a in plan.nodes())
    fits = [
        e
        for e in check_task(task).embodiments
        if e in ALL_EMBODIMENTS
        and used <= set(ALL_EMBODIMENTS[e].arms)
        and (not two or len(ALL_EMBODIMENTS[e].arms) >= 2)
    ]
    which = f"{embodiment!r}, the default of task {task!r}" if default else repr(embodiment)
    hint = f"; the task also runs on {' and '.join(fits)}, which fit{'s' if len(fits) == 1 else ''}: set `embodiment`"
    details = "; ".join(f"{path}: {message}" for path, message in errors)
    return f"plan: does not fit embodiment {which}: {details}{hint if fits else ''}"
