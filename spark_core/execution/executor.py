"""Runs a typed Plan against an Actuator and a Resolver: late label binding, post-conditions, recovery tiers,
concurrent arm branches, step-through control, and a complete event trail."""

from __future__ import annotations

import threading
from collections.abc import Callable, Mapping
from dataclasses import dataclass

from ..grammar import Composite, CompositeType, Node, Plan, PrimitiveCall, walk
from ..grammar.tree import child_path
from ..perception import Keypoint, LabelNotFound
from .events import EventBus, EventKind
from .protocols import ActionOutcome, Actuator, FailureKind, Resolver
from .recovery import PERTURB, REDETECT, REPLAN, RecoveryPolicy
from .result import NodeRecord, NodeStatus, TrialResult
from .step_control import Aborted, StepControl
from .turns import Turns

BOTH_ARMS = "both"
# Label-binding moves that position the hand for the label-free primitives after them (grasp, release, ...).
# When such a follower fails and is retried after re-detection, the anchor move is re-run first with fresh
# keypoints: re-detecting is useless if the hand stays where the stale keypoint put it.
ANCHOR_MOVES = frozenset({"move_to_keypoint", "move_above", "move_to_keypoint_arm"})
_KEEPS_ANCHOR = frozenset({"grasp", "release", "wait", "wiggle", "grasp_perturb", "redetect"})


@dataclass(frozen=True)
class Failure:
    kind: FailureKind
    node_path: str
    reason: str


@dataclass(frozen=True)
class ReplanRequest:
    """What a tier-3 replanner gets: the plan that failed and why."""

    plan: Plan
    failure: Failure


Replanner = Callable[[ReplanRequest], "Plan | None"]


class _Barriers:
    """Named rendezvous points for the branches of one `parallel` node (sync_barrier)."""

    def __init__(self, parties: int):
        self.parties = parties
        self._lock = threading.Lock()
        self._by_name: dict[str, threading.Barrier] = {}
        self._failed = False
        # branches taking turns (a simulated world) meet by counting arrivals instead of blocking in a Barrier
        self._arrived: dict[str, int] = {}
        self.waiting = 0  # branches waiting at some barrier now
        self.finished = 0  # branches that ended

    @property
    def failed(self) -> bool:
        return self._failed

    def arrive(self, name: str) -> int:
        """Count an arrival at `name` (turn-taking); returns its ticket (1, 2, ...: cumulative over rounds)."""
        with self._lock:
            self._arrived[name] = self._arrived.get(name, 0) + 1
            return self._arrived[name]

    def complete(self, name: str, ticket: int) -> bool:
        """Whether every branch has arrived for the round of `ticket`."""
        with self._lock:
            return self._arrived.get(name, 0) >= -(-ticket // self.parties) * self.parties

    def get(self, name: str) -> threading.Barrier:
        with self._lock:
            barrier = self._by_name.setdefault(name, threading.Barrier(self.parties))
            if self._failed:  # a branch already failed: nobody may wait for it
                barrier.abort()
            return barrier

    def abort_all(self) -> None:
        """A branch failed: release the others' waits (present and future) instead of leaving them blocked."""
        with self._lock:
            self._failed = True
            for b in self._by_name.values():
                b.abort()


class Executor:
    """One executor per trial. `run` may be called once; control and bus are usable from other threads."""

    def __init__(
        self,
        actuator: Actuator,
        resolver: Resolver,
        *,
        bus: EventBus | None = None,
        control: StepControl | None = None,
        recovery: RecoveryPolicy = RecoveryPolicy(),
        replanner: Replanner | None = None,
        success_check: Callable[[], bool] | None = None,
        trial_id: str = "",
    ):
        self.actuator = actuator
        self.resolver = resolver
        world = getattr(actuator, "world", None)  # a primitive library acts in a world: stamp its sim time
        self.bus = bus or EventBus(trial_id, sim_clock=(lambda: world.sim_time_s) if world is not None else None)
        self.control = control or StepControl()
        self.recovery = recovery
        self.replanner = replanner
        self.success_check = success_check
        self.trial_id = trial_id or self.bus.trial_id
        self.records: dict[str, NodeRecord] = {}
        self._lock = threading.Lock()
        self._turns: Turns | None = None  # parallel branches on a simulated world take turns (see turns.py)
        self._last_started = ""  # the primitive an abort interrupts (named in the aborted failure)

    # -- public ------------------------------------------------------------------------------------------------
    def run(self, plan: Plan) -> TrialResult:
        t_start = self.bus.now()
        replans = 0
        outcome, failure, sim_s = "success", None, 0.0
        monitors = getattr(getattr(self.actuator, "world", None), "monitors", None)
        if isinstance(monitors, list):  # a simulated world calls its monitors every control period (10 ms sim)
            monitors.append(self._abort_within_a_tick)
            # after every other monitor: a branch aborted or out of time unwinds before passing the turn
            self._turns = Turns(getattr(getattr(self.actuator, "world", None), "_lock", None))
            monitors.append(self._turns)
        try:
            prefix = ""
            while True:
                self._add_records(plan, prefix)
                failure, s = self._run_node(plan.tree, prefix + "tree", None, None)
                sim_s += s
                if failure is None or not self._can_replan(replans):
                    break
                replans += 1
                self.bus.publish(
                    prefix + "tree", EventKind.RETRYING, tier=REPLAN, attempt=replans, reason=failure.reason
                )
                new_plan = self.replanner(ReplanRequest(plan, failure))  # type: ignore[misc]
                if new_plan is None:
                    break
                plan, prefix = new_plan, f"replan[{replans}]."
            # An abort the primitive could not see (a world without monitors) still never ends as a success.
            self.control.check_abort(self._last_started or "tree")
            if failure is None and self.success_check is not None and not self.success_check():
                failure = Failure(
                    FailureKind.PLANNER, "tree", "every node succeeded but the task's success predicate is false"
                )
            if failure is not None:
                outcome = "failure"
        except Aborted as e:
            outcome, failure = "aborted", Failure(FailureKind.CONTROL, str(e), "aborted by the operator")
            for rec in self.records.values():
                if rec.status in (NodeStatus.PENDING, NodeStatus.RUNNING):
                    rec.status = NodeStatus.ABORTED.value
        finally:
            if isinstance(monitors, list) and self._abort_within_a_tick in monitors:
                monitors.remove(self._abort_within_a_tick)
            if isinstance(monitors, list) and self._turns is not None and self._turns in monitors:
                monitors.remove(self._turns)
            self.bus.close()
        return TrialResult(
            trial_id=self.trial_id,
            outcome=outcome,
            failure=None if failure is None or outcome == "aborted" else failure.kind,
            failed_node=failure.node_path if failure else None,
            reason=failure.reason if failure else "",
            nodes=self.records,
            events=list(self.bus.history),
            wall_time_s=self.bus.now() - t_start,
            sim_time_s=sim_s,
            replans=replans,
        )

    # -- tree walking ------------------------------------------------------------------------------------------
    def _can_replan(self, replans: int) -> bool:
        return self.recovery.replan and self.replanner is not None and replans < self.recovery.max_replans

    def _add_records(self, plan: Plan, prefix: str) -> None:
        for path, node, arm in walk(plan.tree, prefix + "tree"):
            kind = node.primitive if isinstance(node, PrimitiveCall) else node.type.value
            self.records[path] = NodeRecord(path=path, kind=kind, arm=arm)

    def _begin(self, path: str, **detail) -> NodeRecord:
        rec = self.records[path]
        rec.status = NodeStatus.RUNNING.value
        rec.started_t = self.bus.now()
        self.bus.publish(path, EventKind.STARTED, **detail)
        return rec

    def _finish(self, rec: NodeRecord, failure: Failure | None, **detail) -> None:
        rec.finished_t = self.bus.now()
        if failure is None:
            rec.status = NodeStatus.SUCCEEDED.value
            self.bus.publish(rec.path, EventKind.SUCCEEDED, **detail)
        else:
            rec.status = NodeStatus.FAILED.value
            rec.failure = failure.kind
            rec.reason = failure.reason
            self.bus.publish(rec.path, EventKind.FAILED, failure=failure.kind.value, reason=failure.reason, **detail)

    def _run_node(
        self, node: Node, path: str, arm: str | None, barriers: _Barriers | None, anchor: PrimitiveCall | None = None
    ) -> tuple[Failure | None, float]:
        arm = node.arm or arm
        if isinstance(node, PrimitiveCall):
            return self._run_primitive(node, path, arm, barriers, anchor)
        rec = self._begin(path, type=node.type.value)
        if node.type is CompositeType.PARALLEL:
            failure, sim_s = self._run_parallel(node, path, arm)
        else:
            failure, sim_s, anchor = None, 0.0, None
            for i, child in enumerate(node.children):
                failure, s = self._run_node(child, child_path(path, i), arm, barriers, anchor)
                sim_s += s
                if isinstance(child, PrimitiveCall) and (child.labels or child.primitive not in _KEEPS_ANCHOR):
                    anchor = child if child.primitive in ANCHOR_MOVES else None
                if (failure is None) == (node.type is CompositeType.FALLBACK):
                    break  # sequence stops at the first failure, fallback at the first success
        rec.sim_time_s = sim_s
        self._finish(rec, failure)
        return failure, sim_s

    def _run_parallel(self, node: Composite, path: str, arm: str | None) -> tuple[Failure | None, float]:
        barriers = _Barriers(len(node.children))
        results: list[tuple[Failure | None, float] | BaseException] = [Aborted(path)] * len(node.children)

        turns = self._turns

        def branch(i: int, child: Node) -> None:
            try:
                if turns is not None:
                    turns.begin()
                results[i] = self._run_node(child, child_path(path, i), arm, barriers)
                if results[i][0] is not None:  # type: ignore[index]
                    barriers.abort_all()
            except BaseException as e:
                results[i] = e
                barriers.abort_all()
            finally:
                barriers.finished += 1
                if turns is not None:
                    turns.end()

        threads = [
            threading.Thread(target=branch, args=(i, c), name=f"{path}[{i}]", daemon=True)
            for i, c in enumerate(node.children)
        ]
        if turns is not None:
            turns.spawn(threads)
        for t in threads:
            t.start()
        for t in threads:
            t.join()  # the implicit barrier at the end of a parallel node
        for r in results:
            if isinstance(r, BaseException):
                raise r
        failures = [r[0] for r in results if r[0] is not None]  # type: ignore[index]
        return (failures[0] if failures else None), max(r[1] for r in results)  # type: ignore[index]

    # -- primitives --------------------------------------------------------------------------------------------
    def _run_primitive(
        self, call: PrimitiveCall, path: str, arm: str | None, barriers: _Barriers | None, anchor: PrimitiveCall | None
    ) -> tuple[Failure | None, float]:
        spec = call.spec
        arm = BOTH_ARMS if spec.uses_both_arms else (arm or self.actuator.arms[0])
        self.control.checkpoint(path, lambda p, why: self.bus.publish(p, EventKind.PAUSED, reason=why))
        rec = self._begin(path, primitive=call.primitive, arm=arm)
        self._last_started = path
        embodiment_error = self._embodiment_error(arm)
        if embodiment_error:
            failure = Failure(FailureKind.PLANNER, path, embodiment_error)
            self._finish(rec, failure, attempts=0)
            return failure, 0.0
        keypoints: dict[str, Keypoint] = {}
        while True:
            rec.attempts += 1
            outcome, keypoints = self._attempt(call, arm, barriers, keypoints)
            rec.sim_time_s += outcome.sim_time_s
            if outcome.ok:
                self._finish(rec, None, attempts=rec.attempts, sim_time_s=round(rec.sim_time_s, 4), **outcome.detail)
                return None, rec.sim_time_s
            tier = self.recovery.tier_for(spec, rec.retries + 1, outcome.failure)
            if tier is None or call.primitive == "sync_barrier":  # a missed rendezvous cannot be retried alone
                failure = Failure(outcome.failure or FailureKind.CONTROL, path, outcome.reason)
                self._finish(rec, failure, attempts=rec.attempts, sim_time_s=round(rec.sim_time_s, 4))
                return failure, rec.sim_time_s
            rec.retries += 1
            action = spec.perturbation if tier == PERTURB else "retract+redetect"
            reanchor = anchor if tier == REDETECT and not call.labels else None
            if reanchor is not None:  # tier REDETECT: action is "retract+redetect"
                action = f"{action}+reapproach:{reanchor.primitive}"
            rec.recoveries.append(f"tier{tier}:{action}")
            self.bus.publish(
                path,
                EventKind.RETRYING,
                attempt=rec.retries,
                tier=tier,
                action=action,
                failure=(outcome.failure or FailureKind.CONTROL).value,
                reason=outcome.reason,
            )
            rec.sim_time_s += self._recover(tier, call, arm, keypoints, reanchor)
            self.control.check_abort(path)

    def _abort_within_a_tick(self, _world: object) -> None:
        """World monitor: an abort stops the running motion at the next control period, not at the next node."""
        if self.control.aborted:
            raise Aborted(self._last_started or "tree")

    def _embodiment_error(self, arm: str) -> str:
        arms = tuple(self.actuator.arms)
        if arm == BOTH_ARMS:
            return "" if len(arms) >= 2 else f"needs two arms; this embodiment has {', '.join(arms)}"
        if arm not in arms:
            return f"arm {arm!r} does not exist on this embodiment (arms: {', '.join(arms)})"
        return ""

    def _attempt(
        self, call: PrimitiveCall, arm: str, barriers: _Barriers | None, previous: Mapping[str, Keypoint]
    ) -> tuple[ActionOutcome, dict[str, Keypoint]]:
        spec = call.spec
        if call.primitive == "sync_barrier":
            return self._sync(call, barriers), dict(previous)
        if call.primitive == "redetect":
            self.resolver.refresh()
        if call.primitive == "replan":
            return ActionOutcome.fail(
                "a replan node needs tier-3 recovery enabled with a planner", FailureKind.PLANNER
            ), {}
        keypoints: dict[str, Keypoint] = {}
        try:
            for label in call.labels:  # late binding: resolve NOW, from the latest perception
                keypoints[label] = self.resolver.resolve(label)
        except LabelNotFound as e:
            return ActionOutcome.fail(str(e), FailureKind.PERCEPTION), keypoints
        if call.primitive == "redetect":
            return ActionOutcome.success(0.0), keypoints
        scale = getattr(self.actuator, "timeout_scale", None)  # a slower embodiment's allowance (robosuite's wrist)
        timeout_s = spec.timeout_s * (scale(arm) if scale is not None else 1.0)
        outcome = self.actuator.perform(call, keypoints, arm, timeout_s)
        if outcome.sim_time_s > timeout_s + 1e-9:
            outcome = ActionOutcome.fail(
                f"{call.primitive} exceeded its timeout of {timeout_s:g} s (took {outcome.sim_time_s:.2f} s)",
                FailureKind.TIMEOUT,
                outcome.sim_time_s,
            )
        return outcome, keypoints

    def _sync(self, call: PrimitiveCall, barriers: _Barriers | None) -> ActionOutcome:
        if barriers is None or barriers.parties == 1:
            return ActionOutcome.success(0.0)
        name = call.args.get("name", "sync")
        if self._turns is not None and self._turns.taking_turns():
            return self._sync_in_turns(call, barriers, name)
        try:
            barriers.get(name).wait(timeout=call.spec.timeout_s)  # wall seconds: branches are free threads here
        except threading.BrokenBarrierError:
            return ActionOutcome.fail(
                f"sync_barrier {name!r}: another branch failed or never arrived", FailureKind.CONTROL
            )
        return ActionOutcome.success(0.0)

    def _sync_in_turns(self, call: PrimitiveCall, barriers: _Barriers, name: str) -> ActionOutcome:
        """sync_barrier between branches taking turns: pass the turn until every branch has arrived. Its timeout is
        simulated seconds, as every primitive's (the other branches' motions advance the world's clock); a wall-clock
        wait failed on a loaded machine where the same trial passes on a quiet one."""
        assert self._turns is not None
        world = getattr(self.actuator, "world", None)
        t0 = world.sim_time_s if world is not None else 0.0
        ticket = barriers.arrive(name)
        barriers.waiting += 1
        try:
            while not barriers.complete(name, ticket):
                if barriers.failed or barriers.waiting >= barriers.parties - barriers.finished:
                    return ActionOutcome.fail(
                        f"sync_barrier {name!r}: another branch failed or never arrived", FailureKind.CONTROL
                    )
                waited_s = (world.sim_time_s - t0) if world is not None else 0.0
                if waited_s > call.spec.timeout_s:
                    return ActionOutcome.fail(
                        f"sync_barrier {name!r}: the other branches did not arrive within {call.spec.timeout_s:g} s",
                        FailureKind.TIMEOUT,
                        waited_s,
                    )
                self._turns.pass_turn()
                self.control.check_abort(self._last_started or "tree")
        finally:
            barriers.waiting -= 1
        return ActionOutcome.success(0.0)

    def _recover(
        self,
        tier: int,
        call: PrimitiveCall,
        arm: str,
        keypoints: Mapping[str, Keypoint],
        reanchor: PrimitiveCall | None = None,
    ) -> float:
        """Run a recovery action; returns its simulated seconds. Its own failure is not fatal: the retry decides."""
        if tier == PERTURB and call.spec.perturbation:
            perturb = PrimitiveCall(call.spec.perturbation)
            return self.actuator.perform(perturb, keypoints, arm, perturb.spec.timeout_s).sim_time_s
        if tier == REDETECT:
            sim_s = 0.0
            if arm != BOTH_ARMS and call.spec.perturbation == "grasp_perturb":
                # a failed grasp leaves the fingers closed: reopen so the re-approach does not land on the object
                release = PrimitiveCall("release")
                sim_s += self.actuator.perform(release, {}, arm, release.spec.timeout_s).sim_time_s
            if arm != BOTH_ARMS:
                retract = PrimitiveCall("move_relative", {"dz": self.recovery.retract_m})
                sim_s += self.actuator.perform(retract, {}, arm, retract.spec.timeout_s).sim_time_s
            self.resolver.refresh()
            if reanchor is not None:
                try:
                    fresh = {label: self.resolver.resolve(label) for label in reanchor.labels}
                except LabelNotFound:
                    return sim_s  # the retry's own resolution reports the perception failure
                sim_s += self.actuator.perform(reanchor, fresh, arm, reanchor.spec.timeout_s).sim_time_s
            return sim_s
        return 0.0
