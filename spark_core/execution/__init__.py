"""Execution: runs typed plans with late label binding, post-conditions, recovery and step-through control."""

from .control import Aborted, StepControl
from .events import EVENT_KINDS, Event, EventBus
from .executor import BOTH_ARMS, Executor, Failure, ReplanRequest
from .protocols import ActionOutcome, Actuator, FailureKind, Resolver
from .recovery import PERTURB, REDETECT, REPLAN, RecoveryPolicy
from .result import NodeRecord, TrialResult

__all__ = [
    "Aborted", "ActionOutcome", "Actuator", "BOTH_ARMS", "EVENT_KINDS", "Event", "EventBus", "Executor", "Failure",
    "FailureKind", "NodeRecord", "PERTURB", "REDETECT", "REPLAN", "RecoveryPolicy", "ReplanRequest", "Resolver",
    "StepControl", "TrialResult",
]
