"""Delete and restore against a purge that lands between reading the trial and writing it: the write is one
conditional UPDATE, so the loser is told 'no such trial' instead of failing (StaleDataError, a 500 in the API)."""

from collections.abc import Iterator
from contextlib import contextmanager

from sqlalchemy import event
from sqlalchemy.orm import Session

from spark_core.trace import TraceStore
from spark_core.trace.models import TrialRow


@contextmanager
def _purge_just_before_the_write(store: TraceStore, trial_id: str) -> Iterator[None]:
    """Purge `trial_id` through the store's own API (its own session) at the last moment before the delete or
    restore inside the block writes: before an ORM flush (a read-then-write) or before a Core UPDATE of trials."""
    fired: list[bool] = []

    def purge() -> None:
        if not fired:
            fired.append(True)
            assert store.purge_trial(trial_id)

    def before_flush(session, flush_context, instances):
        if any(isinstance(o, TrialRow) and o.id == trial_id for o in session.dirty):
            purge()

    def before_update(state):
        if state.is_update and state.statement.table.name == "trials":
            purge()

    event.listen(Session, "before_flush", before_flush)
    event.listen(Session, "do_orm_execute", before_update)
    try:
        yield
    finally:
        event.remove(Session, "before_flush", before_flush)
        event.remove(Session, "do_orm_execute", before_update)
    assert fired, "the purge never ran: the test did not race anything"


def test_a_delete_that_loses_to_a_purge_says_there_is_no_such_trial(tmp_path):
    store = TraceStore(f"sqlite:///{tmp_path / 'spark.db'}")
    store.create_trial("t1", task="lift_block", status="done", success=True)
    with _purge_just_before_the_write(store, "t1"):
        assert store.delete_trial("t1") is None
    assert store.get_trial("t1") is None and store.trial_ids() == []


def test_a_restore_that_loses_to_a_purge_says_there_is_no_such_trial(tmp_path):
    store = TraceStore(f"sqlite:///{tmp_path / 'spark.db'}")
    store.create_trial("t1", task="lift_block", status="done", success=True)
    assert store.delete_trial("t1") is not None
    with _purge_just_before_the_write(store, "t1"):
        assert store.restore_trial("t1", grace_s=60) is False
    assert store.get_trial("t1") is None


def test_delete_and_restore_still_keep_their_rules(tmp_path):
    store = TraceStore(f"sqlite:///{tmp_path / 'spark.db'}")
    store.create_trial("t1", task="lift_block", status="done", success=True)
    assert store.delete_trial("t1") is not None and store.delete_trial("t1") is None  # once
    assert store.restore_trial("t1", grace_s=0) is False  # past the grace period
    assert store.restore_trial("t1", grace_s=60) is True and store.restore_trial("t1", grace_s=60) is False
    assert store.get_trial("t1")["id"] == "t1"
