"""TraceStore: create, update, list and read trial records. Migrations are applied when it opens.

Deletion is soft: a deleted trial is hidden from every read (get, list, batches, ids for exports) and can be
restored within a grace period; purging removes the record and its artifact directory for good."""

from __future__ import annotations

import shutil
import threading
from collections.abc import Callable, Iterable
from datetime import UTC, datetime, timedelta
from pathlib import Path
from typing import TYPE_CHECKING, Any, cast

from sqlalchemy import Text, case, create_engine, delete, event, func, not_, or_, select, update
from sqlalchemy import cast as sql_cast
from sqlalchemy.orm import selectinload, sessionmaker

from .models import BatchRow, EventRow, GroundingRow, PlanLibraryRow, TrialRow

if TYPE_CHECKING:
    from sqlalchemy import CursorResult

    from .lease import StoreLease

MIGRATIONS_DIR = Path(__file__).resolve().parents[2] / "migrations"
SORTABLE = {
    "created_at",
    "task",
    "outcome",
    "verdict",
    "seed",
    "planner",
    "segmenter",
    "wall_time_s",
    "sim_time_s",
    "cost_usd",
    "status",
    "batch_id",
    "failure",  # the failing module (FailureKind value)
}


def alembic_config(url: str, connection=None):
    from alembic.config import Config

    cfg = Config()
    cfg.set_main_option("script_location", str(MIGRATIONS_DIR))
    cfg.set_main_option("sqlalchemy.url", url)
    if connection is not None:
        cfg.attributes["connection"] = connection
    return cfg


def store_url(value: str) -> str:
    """A trace store given as a SQLAlchemy URL, or as a plain file path (a SQLite file: `var/x.db`)."""
    return value if "://" in value else f"sqlite:///{value}"


class TraceStore:
    """One store per process; thread-safe through SQLAlchemy sessions. SQLite files use WAL. `url`: a SQLAlchemy
    URL or a SQLite file path."""

    def __init__(self, url: str = "sqlite:///var/spark.db", migrate: bool = True):
        url = store_url(url)
        if url.startswith("sqlite:///") and not url.startswith("sqlite:///:memory:"):
            Path(url[len("sqlite:///") :]).parent.mkdir(parents=True, exist_ok=True)
        self.url = url
        self.engine = create_engine(url, connect_args={"check_same_thread": False} if url.startswith("sqlite") else {})
        if url.startswith("sqlite"):
            event.listen(self.engine, "connect", _sqlite_pragmas)
        self.Session = sessionmaker(self.engine, expire_on_commit=False)
        self._lock = threading.Lock()
        if migrate:
            self.upgrade()

    # -- schema -------------------------------------------------------------------------------------------------
    def upgrade(self, revision: str = "head") -> None:
        from alembic import command

        self._migrate(lambda conn: command.upgrade(alembic_config(self.url, conn), revision))

    def downgrade(self, revision: str = "base") -> None:
        from alembic import command

        self._migrate(lambda conn: command.downgrade(alembic_config(self.url, conn), revision))

    def _migrate(self, run: Callable[[Any], None]) -> None:
        """Run a migration in one transaction. On SQLite, foreign keys are off while it runs: a batch migration
        rebuilds `trials` (copy, drop, rename), and dropping it with foreign keys on cascades to every event and
        grounding. The pragma only takes effect outside a transaction, hence before `begin`; the keys are checked
        before the commit instead."""
        sqlite = self.engine.dialect.name == "sqlite"
        with self.engine.connect() as conn:
            if sqlite:
                conn.exec_driver_sql("PRAGMA foreign_keys=OFF")
                conn.commit()
            try:
                with conn.begin():
                    run(conn)
                    if sqlite and (bad := conn.exec_driver_sql("PRAGMA foreign_key_check").fetchall()):
                        raise RuntimeError(f"migration left {len(bad)} rows whose trial is missing (first: {bad[0]})")
            finally:
                if sqlite:
                    conn.exec_driver_sql("PRAGMA foreign_keys=ON")
                    conn.commit()

    # -- writes -------------------------------------------------------------------------------------------------
    def create_trial(self, trial_id: str, **fields: Any) -> None:
        with self.Session.begin() as s:
            s.add(TrialRow(id=trial_id, **fields))

    def update_trial(self, trial_id: str, **fields: Any) -> None:
        with self.Session.begin() as s:
            row = s.get(TrialRow, trial_id)
            if row is None:
                raise KeyError(f"no trial {trial_id!r}")
            for k, v in fields.items():
                setattr(row, k, v)

    def begin_attempt(self, trial_id: str, **fields: Any) -> int:
        """Start (another) attempt at a trial whose id was decided before it was submitted: create its row, or,
        if a previous attempt left one (a worker killed mid-trial, then retried), drop that attempt's events and
        groundings and overwrite the row. Either way the store ends with the trial once. The attempt number
        (1 for the first) is returned. A concurrent first write of the same id (IntegrityError) counts as a
        previous attempt."""
        from sqlalchemy import exc

        for _ in range(2):
            with self.Session.begin() as s:
                row = s.get(TrialRow, trial_id)
                if row is not None:
                    attempt = int((row.protocol or {}).get("attempt", 1)) + 1 if row.status == "running" else 1
                    s.execute(delete(EventRow).where(EventRow.trial_id == trial_id))
                    s.execute(delete(GroundingRow).where(GroundingRow.trial_id == trial_id))
                    for k, v in fields.items():
                        setattr(row, k, v)
                    if attempt > 1:  # said in the record: this trial's worker died once and it ran again
                        row.protocol = {**(row.protocol or {}), "attempt": attempt}
                        row.artifacts = []  # the dead attempt's images (stored as it ran) are not this one's
                    return attempt
            try:
                with self.Session.begin() as s:
                    s.add(TrialRow(id=trial_id, **fields))
                return 1
            except exc.IntegrityError:
                continue
        raise RuntimeError(f"trial {trial_id!r}: could neither create nor take over its row")

    def add_events(self, trial_id: str, events: Iterable[dict]) -> None:
        with self.Session.begin() as s:
            s.add_all(
                EventRow(
                    trial_id=trial_id,
                    seq=e["seq"],
                    t=e["t"],
                    t_sim=e.get("t_sim"),
                    node_path=e["node_path"],
                    kind=e["kind"],
                    detail=_jsonable(e.get("detail", {})),
                )
                for e in events
            )

    def add_groundings(self, trial_id: str, groundings: Iterable[dict]) -> None:
        with self.Session.begin() as s:
            s.add_all(GroundingRow(trial_id=trial_id, label=g["label"], record=_jsonable(g)) for g in groundings)

    # -- deletion -----------------------------------------------------------------------------------------------
    def delete_trial(self, trial_id: str) -> datetime | None:
        """Hide the trial from every read (restorable with `restore_trial`); when it was deleted, or None if
        there is no such (visible) trial."""
        now = _now()
        # one conditional UPDATE, not read-then-write: a purge (or another delete) between the read and the write
        # left the ORM updating a row that was gone (StaleDataError, a 500), and two deletes at once both succeeded
        with self.Session.begin() as s:
            done = cast(
                "CursorResult[Any]",
                s.execute(
                    update(TrialRow)
                    .where(TrialRow.id == trial_id, TrialRow.deleted_at.is_(None))
                    .values(deleted_at=now)
                    .execution_options(synchronize_session=False)
                ),
            )
        return now if done.rowcount == 1 else None

    def restore_trial(self, trial_id: str, grace_s: float) -> bool:
        """Undo a delete made within the last `grace_s` seconds; False if there is no such deleted trial."""
        cutoff = _now() - timedelta(seconds=grace_s)
        with self.Session.begin() as s:  # one conditional UPDATE, for the same reason as delete_trial's
            done = cast(
                "CursorResult[Any]",
                s.execute(
                    update(TrialRow)
                    .where(TrialRow.id == trial_id, TrialRow.deleted_at.is_not(None), TrialRow.deleted_at >= cutoff)
                    .values(deleted_at=None)
                    .execution_options(synchronize_session=False)
                ),
            )
        return done.rowcount == 1

    def purge_trial(self, trial_id: str, artifacts_dir: str | Path | None = None) -> bool:
        """Remove the trial for good (deleted or not): its record, events, groundings, the plan it gave the plan
        library (LLM planners must not keep seeing a purged trial's instruction and plan) and, given the
        artifacts directory, its files there. False if there is no such record."""
        with self.Session.begin() as s:
            paths = s.scalar(select(TrialRow.artifacts).where(TrialRow.id == trial_id))
            s.execute(delete(EventRow).where(EventRow.trial_id == trial_id))
            s.execute(delete(GroundingRow).where(GroundingRow.trial_id == trial_id))
            s.execute(delete(PlanLibraryRow).where(PlanLibraryRow.trial_id == trial_id))
            deleted = cast("CursorResult[Any]", s.execute(delete(TrialRow).where(TrialRow.id == trial_id)))
            if deleted.rowcount == 0:
                return False
        if artifacts_dir is not None:
            _remove_artifacts(Path(artifacts_dir), trial_id, paths or [])
        return True

    def purge_deleted(self, grace_s: float, artifacts_dir: str | Path | None = None) -> list[str]:
        """Purge every trial deleted more than `grace_s` seconds ago; their ids."""
        cutoff = _now() - timedelta(seconds=grace_s)
        with self.Session() as s:
            ids = list(
                s.scalars(select(TrialRow.id).where(TrialRow.deleted_at.is_not(None), TrialRow.deleted_at < cutoff))
            )
        return [i for i in ids if self.purge_trial(i, artifacts_dir)]

    # -- restarts -----------------------------------------------------------------------------------------------
    def interrupt_unfinished(
        self,
        reason: str = "the server stopped while the trial was running",
        *,
        lease: StoreLease | None = None,
        keep_queued: bool = False,
    ) -> int:
        """At start-up: trials left running by a previous process are marked interrupted, not lost; so are
        queued ones unless `keep_queued` (the console re-queues them). Acts only for the holder of the console
        lease, or when nobody live holds it: another server's trials are its own (LeaseHeld otherwise)."""
        from .lease import StoreLease

        (lease or StoreLease(self)).refuse_if_held()
        states = ("running",) if keep_queued else ("queued", "running")
        with self.Session.begin() as s:
            rows = s.scalars(select(TrialRow).where(TrialRow.status.in_(states), TrialRow.deleted_at.is_(None))).all()
            for row in rows:
                never_started = row.status == "queued"
                row.status, row.outcome, row.verdict = "interrupted", "aborted", "interrupted"
                row.reason = "the server stopped before the trial started" if never_started else reason
            return len(rows)

    def queued_trials(self) -> list[dict]:
        """Trials recorded as queued that never started, oldest first: {id, protocol}."""
        with self.Session() as s:
            rows = s.execute(
                select(TrialRow.id, TrialRow.protocol)
                .where(TrialRow.status == "queued", TrialRow.deleted_at.is_(None))
                .order_by(TrialRow.created_at, TrialRow.id)
            ).all()
        return [{"id": r.id, "protocol": r.protocol or {}} for r in rows]

    def create_batch(self, batch_id: str, spec: dict) -> None:
        with self.Session.begin() as s:
            s.add(BatchRow(id=batch_id, spec=_jsonable(spec)))

    def set_batch_manifest(self, batch_id: str, manifest: dict) -> None:
        """Keep the run's manifest (spark_core.bench.manifest) in the batch's spec, under `manifest`."""
        with self.Session.begin() as s:
            row = s.get(BatchRow, batch_id)
            if row is None:
                raise KeyError(f"no batch {batch_id!r}")
            row.spec = {**(row.spec or {}), "manifest": _jsonable(manifest)}

    def set_batch_status(self, batch_id: str, status: str) -> None:
        with self.Session.begin() as s:
            row = s.get(BatchRow, batch_id)
            if row is None:
                raise KeyError(f"no batch {batch_id!r}")
            row.status = status

    def delete_batch(self, batch_id: str) -> bool:
        """Remove the batch's record (status, spec, manifest); False if there is none. Its trials are kept as they
        were recorded, each still naming the batch it ran in (`trials.batch_id` has no foreign key: a trial
        outlives its batch, and `trial_ids(batch=...)` still finds them)."""
        with self.Session.begin() as s:
            row = s.get(BatchRow, batch_id)
            if row is None:
                return False
            s.delete(row)
        return True

    def has_batch(self, batch_id: str) -> bool:
        with self.Session() as s:
            return s.scalar(select(BatchRow.id).where(BatchRow.id == batch_id)) is not None

    def get_batch(self, batch_id: str) -> dict | None:
        """The batch, its trials' summaries and per-task success."""
        with self.Session() as s:
            row = s.get(BatchRow, batch_id)
            if row is None:
                return None
            members = s.scalars(
                select(TrialRow).where(TrialRow.batch_id == batch_id).order_by(TrialRow.task, TrialRow.seed)
            ).all()
            items = [_row_dict(t, summary=True) for t in members if t.deleted_at is None]
            # deleted members stay counted in the batch's results (a delete must not rewrite a benchmark)
            deleted = [_row_dict(t, summary=True) for t in members if t.deleted_at is not None]
        return {
            "id": row.id,
            "status": row.status,
            "spec": row.spec,
            "created_at": row.created_at.isoformat() if row.created_at else None,
            "trials": items,
            "deleted_trials": deleted,
        }

    def list_batches(self, limit: int = 100, offset: int = 0) -> tuple[int, list[dict]]:
        """(number of batches, one page newest first): each batch's id, created_at (ISO), stored status, spec, and
        its trials counted (deleted ones too, until purged): total, done (done or interrupted) and successes."""
        done = func.sum(case((TrialRow.status.in_(("done", "interrupted")), 1), else_=0))
        ok = func.sum(case((TrialRow.success.is_(True), 1), else_=0))
        q = (
            select(BatchRow, func.count(TrialRow.id), done, ok)
            .outerjoin(TrialRow, TrialRow.batch_id == BatchRow.id)  # deleted members count: results stay as run
            .group_by(BatchRow.id)
            .order_by(BatchRow.created_at.desc(), BatchRow.id.desc())
            .limit(limit)
            .offset(offset)
        )
        with self.Session() as s:
            total = s.scalar(select(func.count()).select_from(BatchRow)) or 0
            rows = s.execute(q).all()
            items = [
                {
                    "id": b.id,
                    "created_at": b.created_at.isoformat() if b.created_at else None,
                    "status": b.status,
                    "spec": dict(b.spec or {}),
                    "progress": {"done": int(d or 0), "total": int(n or 0), "successes": int(k or 0)},
                }
                for b, n, d, k in rows
            ]
        return int(total), items

    # -- plan library -------------------------------------------------------------------------------------------
    def add_library_plan(
        self, instruction: str, plan_text: str, scene_summary: str = "", trial_id: str | None = None
    ) -> None:
        """Keep a succeeded trial's plan as a few-shot example for later LLM planner calls. Risk: the instruction
        may be a console caller's own text, so it reaches every later LLM prompt (a stored prompt-injection path
        for whoever may submit trials); deleting the trial hides it, purging removes it."""
        with self.Session.begin() as s:
            s.add(
                PlanLibraryRow(
                    instruction=instruction, plan_text=plan_text, scene_summary=scene_summary, trial_id=trial_id
                )
            )

    def library_plans(self) -> list[dict]:
        """Oldest first: {instruction, plan, scene_summary, trial_id, t}. A deleted trial's plan is left out while
        it can still be restored (purging removes it for good)."""
        with self.Session() as s:
            rows = s.scalars(
                select(PlanLibraryRow)
                .outerjoin(TrialRow, TrialRow.id == PlanLibraryRow.trial_id)
                .where(TrialRow.deleted_at.is_(None))
                .order_by(PlanLibraryRow.id)
            ).all()
            return [
                {
                    "instruction": r.instruction,
                    "plan": r.plan_text,
                    "scene_summary": r.scene_summary,
                    "trial_id": r.trial_id,
                    "t": r.created_at.timestamp() if r.created_at else None,
                }
                for r in rows
            ]

    # -- reads --------------------------------------------------------------------------------------------------
    def scene_states(self, trial_id: str) -> list | None:
        """The trial's recorded scene states [(t_s, qpos)], or None (unknown trial, or recorded before 0004)."""
        with self.Session() as s:
            return s.scalar(select(TrialRow.scene_states).where(TrialRow.id == trial_id, TrialRow.deleted_at.is_(None)))

    def has_trial(self, trial_id: str) -> bool:
        """Whether the id is taken (a deleted trial's too, until it is purged)."""
        with self.Session() as s:
            return s.scalar(select(TrialRow.id).where(TrialRow.id == trial_id)) is not None

    def get_trial(self, trial_id: str) -> dict | None:
        with self.Session() as s:
            row = s.scalars(
                select(TrialRow)
                .where(TrialRow.id == trial_id, TrialRow.deleted_at.is_(None))
                .options(selectinload(TrialRow.events), selectinload(TrialRow.groundings))
            ).first()
            if row is None:
                return None
            out = _row_dict(row)
            out["events"] = [
                {"seq": e.seq, "t": e.t, "t_sim": e.t_sim, "node_path": e.node_path, "kind": e.kind, "detail": e.detail}
                for e in row.events
            ]
            out["groundings"] = [g.record for g in row.groundings]
            return out

    def trial_ids(
        self, *, tasks=(), ids=(), batch: str | None = None, success: bool | None = None, since=None, until=None
    ) -> list[str]:
        """Ids of trials matching every given filter, oldest first (export, batch tools)."""
        q = select(TrialRow.id).where(TrialRow.deleted_at.is_(None))
        if tasks:
            q = q.where(TrialRow.task.in_(list(tasks)))
        if ids:
            q = q.where(TrialRow.id.in_(list(ids)))
        if batch:
            q = q.where(TrialRow.batch_id == batch)
        if success is not None:
            q = q.where(TrialRow.success == success)
        if since is not None:
            q = q.where(TrialRow.created_at >= since)
        if until is not None:
            q = q.where(TrialRow.created_at < until)
        with self.Session() as s:
            return list(s.scalars(q.order_by(TrialRow.created_at, TrialRow.id)).all())

    def list_trials(
        self,
        *,
        status: str | None = None,
        task: str | None = None,
        success: bool | None = None,
        batch: str | None = None,
        verdict: str | None = None,
        search: str | None = None,
        training: bool | None = None,
        sort: str = "-created_at",
        limit: int = 50,
        offset: int = 0,
    ) -> tuple[int, list[dict]]:
        """(total matching, one page of summaries). `sort` is a column name, '-' for descending. Each summary
        has `training_frames`: the frames of the trial's training-data capture (what a LeRobot export takes),
        None without one; `training` keeps only the trials with (True) or without (False) one."""
        key = sort.lstrip("-")
        if key not in SORTABLE:
            raise ValueError(f"cannot sort by {key!r}; sortable: {', '.join(sorted(SORTABLE))}")
        where: list[Any] = [TrialRow.deleted_at.is_(None)]  # in the list's indexes (0007): still index-only
        if status and status not in TRIAL_STATUSES:
            raise ValueError(f"status: unknown trial status {status!r}; statuses: {', '.join(TRIAL_STATUSES)}")
        if status:
            where.append(TrialRow.status == status)
        if task:
            where.append(TrialRow.task == task)
        if batch:
            where.append(TrialRow.batch_id == batch)
        if verdict:
            where.append(TrialRow.verdict == verdict)
        if success is not None:
            # Beside a task, test success on the task's rows: SQLite (no statistics) would otherwise walk the
            # 2-valued success index, ~10x the rows. ifnull() keeps its planner off that index; PostgreSQL has
            # statistics (and no ifnull on booleans).
            sqlite_task = task and self.engine.dialect.name == "sqlite"
            where.append(
                func.ifnull(TrialRow.success, -1) == int(success) if sqlite_task else TrialRow.success == success
            )
        if training is not None:  # the artifacts' text names the capture file (no JSON decoding per row)
            where.append(_HAS_CAPTURE if training else or_(TrialRow.artifacts.is_(None), not_(_HAS_CAPTURE)))
        if search:  # literal text: % and _ in it match themselves, not any text
            like = "%" + search.replace("\\", "\\\\").replace("%", "\\%").replace("_", "\\_") + "%"
            where.append(
                or_(
                    TrialRow.instruction.ilike(like, escape="\\"),
                    TrialRow.task.ilike(like, escape="\\"),
                    TrialRow.reason.ilike(like, escape="\\"),
                )
            )
        col = getattr(TrialRow, key)
        # id breaks ties (a stable order across pages) in the same direction, so one index (0006) covers the order
        order = (col.desc(), TrialRow.id.desc()) if sort.startswith("-") else (col.asc(), TrialRow.id.asc())
        if self.engine.dialect.name != "sqlite":
            # An empty value sorts as the smallest, as SQLite does natively (PostgreSQL puts NULLs last ascending)
            first = order[0].nulls_last() if sort.startswith("-") else order[0].nulls_first()
            order = (first, order[1])
        # Two steps: the page's ids from the indexes alone, then only the summary columns of those rows. Decoding
        # the heavy JSON columns (trajectory, plan) was ~90 % of a request; sorting whole rows made offsets slow.
        cols = [c for c in TrialRow.__table__.columns if c.name not in _HEAVY]
        with self.Session() as s:
            total = s.scalar(select(func.count()).select_from(TrialRow).where(*where))
            ids = s.scalars(select(TrialRow.id).where(*where).order_by(*order).limit(limit).offset(offset)).all()
            rows = s.execute(select(*cols).where(TrialRow.id.in_(ids))).mappings().all() if ids else []
            captured = (
                s.execute(select(TrialRow.id, TrialRow.artifacts).where(TrialRow.id.in_(ids), _HAS_CAPTURE)).all()
                if ids
                else []
            )
        frames = {tid: _capture_frames(arts) for tid, arts in captured}
        by_id = {r["id"]: dict(r) for r in rows}
        items = [by_id[i] for i in ids if i in by_id]  # a row deleted between the two reads is left out
        for item in items:
            item["created_at"] = item["created_at"].isoformat() if item["created_at"] else None
            item["training_frames"] = frames.get(item["id"])
        return int(total or 0), items


# not in summaries (deleted_at: always empty on what reads return)
TRIAL_STATUSES = ("queued", "running", "done", "interrupted")  # a trial's life cycle in the store (TrialRow.status)
_HEAVY = frozenset({"plan_tree", "nodes", "trajectory", "plan_text", "artifacts", "scene_states", "deleted_at"})


CAPTURE_FILE = "episode.npz"  # a training-data capture's frames (sim/capture.py; the LeRobot export reads it)
_HAS_CAPTURE = sql_cast(TrialRow.artifacts, Text).like(f'%"{CAPTURE_FILE}"%')


def _capture_frames(artifacts: list | None) -> int | None:
    entry = next((a for a in artifacts or [] if a.get("name") == CAPTURE_FILE), None)
    return None if entry is None else int(entry.get("frames") or 0)


def _sqlite_pragmas(dbapi_conn, _record) -> None:
    cur = dbapi_conn.cursor()
    cur.execute("PRAGMA journal_mode=WAL")
    cur.execute("PRAGMA foreign_keys=ON")
    cur.execute("PRAGMA busy_timeout=30000")  # worker processes write the same file; wait instead of failing
    cur.close()


def _row_dict(row: TrialRow, summary: bool = False) -> dict:
    heavy = {"plan_tree", "nodes", "trajectory", "plan_text", "artifacts"} if summary else set()
    heavy |= {"scene_states", "deleted_at"}  # scene states: deferred, read through scene_states()
    out = {c.name: getattr(row, c.name) for c in TrialRow.__table__.columns if c.name not in heavy}
    out["created_at"] = row.created_at.isoformat() if row.created_at else None
    return out


def _now() -> datetime:
    return datetime.now(UTC)


def _remove_artifacts(root: Path, trial_id: str, entries: list[dict]) -> None:
    """The trial's directory under the artifacts root, and any file its record names under that root; never
    anything outside it."""
    root = root.resolve()
    targets = [root / trial_id, *(Path(str(e.get("path", ""))) for e in entries if isinstance(e, dict))]
    for target in targets:
        try:
            target = target.resolve()
        except OSError:
            continue
        if target == root or not target.is_relative_to(root):
            continue
        if target.is_dir():
            shutil.rmtree(target, ignore_errors=True)
        elif target.exists():
            target.unlink(missing_ok=True)


def _jsonable(value: Any) -> Any:
    """numpy scalars/arrays and other odd values -> plain JSON types."""
    import json

    import numpy as np

    def default(o):
        if isinstance(o, np.generic):
            return o.item()
        if isinstance(o, np.ndarray):
            return o.tolist()
        return str(o)

    return json.loads(json.dumps(value, default=default))
