"""Write a finished trial (result, events, groundings, trajectory) into the trace store."""

from __future__ import annotations

from ..execution import TrialResult
from ..grammar import Plan, plan_to_dict, to_yaml
from .store import TraceStore, _jsonable


def record_trial(store: TraceStore, trial_id: str, *, task: str, instruction: str, seed: int, planner: str,
                 resolver: str, protocol: dict, plan: Plan | None, result: TrialResult | None, success: bool | None,
                 groundings: list[dict] = (), trajectory: list = (), wall_time_s: float | None = None,
                 cost_usd: float = 0.0, usage: dict | None = None, reason: str = "", artifacts: list[dict] = (),
                 scene_states: list | None = None, batch_id: str | None = None) -> None:
    """Create-or-complete the trial row and append its events and groundings in one go."""
    fields = dict(
        status="done", instruction=instruction, task=task, seed=seed, planner=planner, resolver=resolver,
        protocol=_jsonable(protocol), plan_text=to_yaml(plan) if plan else "", plan_tree=plan_to_dict(plan) if plan else None,
        outcome=result.outcome if result else "failure", success=success,
        failure=result.failure.value if result and result.failure else ("planner" if plan is None else None),
        failed_node=result.failed_node if result else None, reason=(result.reason if result else "") or reason,
        wall_time_s=wall_time_s, sim_time_s=result.sim_time_s if result else None, cost_usd=cost_usd,
        usage=usage or {}, nodes=_jsonable({p: r.to_dict() for p, r in result.nodes.items()}) if result else {},
        trajectory=_jsonable(list(trajectory)), artifacts=_jsonable(list(artifacts)),
        scene_states=_jsonable(list(scene_states)) if scene_states else None,
    )
    if batch_id is not None:
        fields["batch_id"] = batch_id
    if store.get_trial(trial_id) is None:
        store.create_trial(trial_id, **fields)
    else:
        store.update_trial(trial_id, **fields)
    if result:
        store.add_events(trial_id, [e.to_dict() for e in result.events])
    store.add_groundings(trial_id, groundings)
