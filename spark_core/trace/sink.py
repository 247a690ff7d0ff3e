"""StoreSink: a trial's record in the trace store, written as the trial runs.

The row is created (or taken over from the console's queue) when the trial starts, every event is written as
it arrives (a crash keeps what happened so far), so is every grounding as it is made (with its annotated
images, when kept: a live trial's camera panel shows them), and the outcome, plan, per-node records,
trajectory, scene states and the other artifact files are written when it ends.
"""

from __future__ import annotations

import threading
from pathlib import Path
from typing import Any

from ..execution import Event
from ..grammar import Plan, plan_to_dict, to_yaml
from ..trial import BaseSink, TrialContext, TrialOutcome
from .grounding_images import GroundingImages
from .store import TraceStore, _jsonable


class StoreSink(BaseSink):
    def __init__(
        self,
        store: TraceStore,
        artifacts_dir: str | Path = "var/artifacts",
        extra_protocol: dict | None = None,
        grounding_images: bool = False,
    ):
        """`grounding_images`: keep one small annotated image per grounding and camera (the console's camera
        panel at its cursor); off by default: drawing each capture's RGB costs batch throughput."""
        self.store = store
        self.artifacts_dir = Path(artifacts_dir)
        self.extra_protocol = extra_protocol or {}
        self._trial_id: str | None = None
        self._attempt = 1  # > 1: a retry after an attempt that died mid-trial (its events were dropped)
        self._grounding_images = GroundingImages() if grounding_images else None
        self._resolver: Any = None
        self._groundings_stored = 0  # the resolver's groundings[:n] are in the store
        self._grounding_lock = threading.Lock()  # parallel branches resolve labels from their own threads

    @staticmethod
    def _config_fields(config: Any) -> dict[str, Any]:
        return dict(
            task=config.task,
            seed=config.seed,
            planner=config.planner,
            segmenter=config.segmenter,
            batch_id=config.batch_id,
        )

    def on_start(self, ctx: TrialContext) -> None:
        self._trial_id = ctx.trial_id
        self._resolver = ctx.resolver
        fields = dict(
            self._config_fields(ctx.config),
            status="running",
            instruction=ctx.instruction,
            protocol=_jsonable({**ctx.protocol, **self.extra_protocol}),
        )
        # The row may exist: queued by the console, or left "running" by an attempt whose worker died (a Ray
        # retry). Either way this attempt takes it over, so the trial is stored once with one attempt's events.
        self._attempt = self.store.begin_attempt(ctx.trial_id, **fields)
        listeners = getattr(ctx.resolver, "grounding_listeners", None)
        if isinstance(listeners, list):  # stored as each grounding is made, with the frames it used
            listeners.append(lambda _record: self._watch_groundings())

    def on_plan(self, ctx: TrialContext, plan: Plan | None, planning: dict[str, Any]) -> None:
        self._watch_groundings()
        if plan is not None:
            # plan_text is the canonical (paper's) form; plan_tree keeps leaves as `primitive:` because the
            # console's tree view (web/app.js renderTree) tells leaves by that key. Both forms parse.
            tree = plan_to_dict(plan, form="primitive")
            self.store.update_trial(ctx.trial_id, plan_text=to_yaml(plan), plan_tree=_jsonable(tree))

    def on_event(self, event: Event) -> None:
        self._watch_groundings()
        if self._trial_id is not None:
            self.store.add_events(self._trial_id, [event.to_dict()])

    def _watch_groundings(self, resolver: Any = None) -> None:
        """Store the groundings made since the last look, and (when kept) write their images and the record's
        list of them: each exactly once, so the end of the trial adds only what is new."""
        resolver = resolver if resolver is not None else self._resolver
        if resolver is None or self._trial_id is None:
            return
        with self._grounding_lock:
            groundings = list(getattr(resolver, "groundings", None) or [])
            new, self._groundings_stored = groundings[self._groundings_stored :], len(groundings)
            if new:
                self.store.add_groundings(self._trial_id, new)
            if self._grounding_images is not None:
                self._grounding_images.watch(resolver)
                if self._grounding_images.save(self.artifacts_dir / self._trial_id):
                    self.store.update_trial(self._trial_id, artifacts=_jsonable(self._grounding_images.entries))

    def on_finish(self, ctx: TrialContext | None, outcome: TrialOutcome) -> None:
        result = outcome.result
        fields: dict[str, Any] = dict(
            status="done",
            verdict=outcome.verdict.value,
            success=outcome.success,
            instruction=outcome.instruction,
            outcome=result.outcome
            if result is not None
            else ("aborted" if outcome.verdict == "aborted" else "failure"),
            failure=outcome.failure,
            failed_node=outcome.failed_node,
            reason=outcome.reason,
            wall_time_s=outcome.wall_time_s,
            sim_time_s=outcome.sim_time_s if result is not None else None,
            phases_s=_jsonable(outcome.phases_s) or None,
            cost_usd=outcome.cost_usd,
            usage=_jsonable(outcome.usage),
            protocol=_jsonable(
                {
                    **outcome.protocol,
                    **self.extra_protocol,
                    "task_success": outcome.task_success,
                    "tree_status": outcome.tree_status,
                    "unmet": outcome.unmet,
                    **({"attempt": self._attempt} if self._attempt > 1 else {}),
                }
            ),
        )
        if result is not None:
            fields["nodes"] = _jsonable({p: r.to_dict() for p, r in result.nodes.items()})
        if ctx is not None:
            world = ctx.world
            rec = getattr(world, "recorder", None)
            if rec is not None:
                fields["trajectory"] = _jsonable(list(rec.rows))
                fields["scene_states"] = _jsonable(list(rec.states)) or None
            fields["artifacts"] = _jsonable(self._artifacts(ctx))
        if not self.store.has_trial(outcome.trial_id):  # never started (cancelled while queued)
            config = ctx.config if ctx is not None else None
            self.store.create_trial(
                outcome.trial_id,
                task=outcome.task,
                seed=outcome.seed,
                **({} if config is None else self._config_fields(config)),
                **fields,
            )
        else:
            self.store.update_trial(outcome.trial_id, **fields)
        if ctx is not None and self._trial_id is None:  # never started: nothing was stored as it ran
            self.store.add_groundings(outcome.trial_id, getattr(ctx.resolver, "groundings", []))

    def _artifacts(self, ctx: TrialContext) -> list[dict]:
        from .artifacts import capture_entries, detection_images, planner_image

        directory = self.artifacts_dir / ctx.trial_id
        if self._trial_id is not None:
            self._watch_groundings(ctx.resolver)  # the last ones (and their images), stored once
        elif self._grounding_images is not None:  # never started: its groundings are stored after the row
            self._grounding_images.watch(ctx.resolver)
            self._grounding_images.save(directory)
        out = detection_images(ctx.resolver, directory)
        if self._grounding_images is not None:
            out += self._grounding_images.entries
        if ctx.extra.get("planner_image") is not None:
            rgb, camera = ctx.extra["planner_image"]
            out.append(planner_image(rgb, camera, directory))
        if ctx.episode is not None:
            ctx.world.monitors.remove(ctx.episode)
            out += capture_entries(ctx.episode, directory)
        return out


__all__ = ["StoreSink"]
