"""Migrating a store keeps what it recorded: every revision up to head and back down to the first, with a
trial's events and groundings in it. (On SQLite, batch migrations rebuild `trials`; with foreign keys on, the
drop cascaded to every event and grounding: a store upgraded from 0004 lost them all.)"""

from __future__ import annotations

from spark_core.trace.store import TraceStore

REVISIONS = [f"{n:04d}" for n in range(1, 10)]

TRIAL = (
    "INSERT INTO trials (id, created_at, status, instruction, task, seed, planner, resolver, protocol, plan_text, "
    "outcome, reason, cost_usd, usage, nodes, trajectory) VALUES ('t1', '2026-01-01 00:00:00', 'done', "
    "'lift the block', 'lift_block', 0, 'rules', 'sim', '{}', '', 'success', '', 0, '{}', '[]', '[]')"
)


def _counts(store: TraceStore) -> tuple[int, int, int]:
    with store.engine.connect() as c:
        return tuple(
            c.exec_driver_sql(f"SELECT count(*) FROM {t}").scalar_one() for t in ("trials", "events", "groundings")
        )  # type: ignore[return-value]


def test_every_migration_keeps_events_and_groundings(store_url):
    store = TraceStore(store_url, migrate=False)
    store.upgrade("0001")
    with store.engine.begin() as c:
        c.exec_driver_sql(TRIAL)
        for seq in range(3):
            c.exec_driver_sql(
                "INSERT INTO events (trial_id, seq, t, node_path, kind, detail) "
                f"VALUES ('t1', {seq}, {seq}.0, '/', 'tick', '{{}}')"
            )
        c.exec_driver_sql("INSERT INTO groundings (trial_id, label, record) VALUES ('t1', 'red block', '{}')")
    assert _counts(store) == (1, 3, 1)
    for rev in REVISIONS[1:]:
        store.upgrade(rev)
        assert _counts(store) == (1, 3, 1), f"after upgrading to {rev}"
    for rev in reversed(REVISIONS[:-1]):
        store.downgrade(rev)
        assert _counts(store) == (1, 3, 1), f"after downgrading to {rev}"


def test_foreign_keys_are_back_on_after_a_migration(tmp_path):
    store = TraceStore(f"sqlite:///{tmp_path / 'trace.db'}")
    store.downgrade("0008")
    store.upgrade()
    with store.engine.connect() as c:
        assert c.exec_driver_sql("PRAGMA foreign_keys").scalar_one() == 1
