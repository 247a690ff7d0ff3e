"""SQLAlchemy models of the trace store. Schema changes go through Alembic (migrations/versions)."""

from __future__ import annotations

from datetime import UTC, date, datetime
from typing import Any

from sqlalchemy import JSON, Boolean, DateTime, Dialect, Float, ForeignKey, Integer, String, Text
from sqlalchemy.orm import DeclarativeBase, Mapped, mapped_column, relationship
from sqlalchemy.types import TypeDecorator


def utcnow() -> datetime:
    return datetime.now(UTC)


def as_utc(value: date | datetime) -> datetime:
    """An instant in UTC (tz-aware). A naive datetime is read as UTC, a date as its midnight UTC; an aware one is
    converted (2026-11-28T12:00+02:00 is 10:00 UTC)."""
    if not isinstance(value, datetime):
        value = datetime(value.year, value.month, value.day)
    return value.replace(tzinfo=UTC) if value.tzinfo is None else value.astimezone(UTC)


class UTCDateTime(TypeDecorator[datetime]):
    """A timestamp that is a UTC instant on every backend, written and read as a tz-aware UTC datetime. SQLite has
    no time zones (DateTime(timezone=True) there is text without an offset, read back naive): an aware value was
    written as its own wall time whatever its offset, and read back naive, so the API served `created_at` with no
    offset. Every value bound (a row's field or a filter's bound: `created_at >= since`) is converted to UTC first,
    a naive one read as UTC; PostgreSQL keeps timestamptz. The DDL is DateTime(timezone=True) as before."""

    impl = DateTime(timezone=True)
    cache_ok = True

    def process_bind_param(self, value: Any, dialect: Dialect) -> datetime | None:
        return None if value is None else as_utc(value)

    def process_result_value(self, value: Any, dialect: Dialect) -> datetime | None:
        return None if value is None else as_utc(value)


class Base(DeclarativeBase):
    pass


class TrialRow(Base):
    """One trial: what was asked, with which backends, the plan, and how it ended."""

    __tablename__ = "trials"

    id: Mapped[str] = mapped_column(String(255), primary_key=True)
    created_at: Mapped[datetime] = mapped_column(UTCDateTime(), default=utcnow, index=True)
    status: Mapped[str] = mapped_column(String(16), default="queued", index=True)  # queued|running|done|interrupted
    instruction: Mapped[str] = mapped_column(Text, default="")
    task: Mapped[str] = mapped_column(String(128), default="", index=True)
    seed: Mapped[int] = mapped_column(Integer, default=0)
    planner: Mapped[str] = mapped_column(String(64), default="")
    segmenter: Mapped[str] = mapped_column(String(128), default="")  # perception backend (catalog name)
    protocol: Mapped[dict] = mapped_column(JSON, default=dict)  # planner, segmenter (privileged or not), versions
    plan_text: Mapped[str] = mapped_column(Text, default="")
    plan_tree: Mapped[dict | None] = mapped_column(JSON, nullable=True)
    outcome: Mapped[str] = mapped_column(String(16), default="", index=True)  # success|failure|aborted
    success: Mapped[bool | None] = mapped_column(Boolean, nullable=True, index=True)
    verdict: Mapped[str | None] = mapped_column(String(16), nullable=True, index=True)  # spark_core.trial.Verdict
    failure: Mapped[str | None] = mapped_column(String(32), nullable=True)
    failed_node: Mapped[str | None] = mapped_column(String(256), nullable=True)
    reason: Mapped[str] = mapped_column(Text, default="")
    wall_time_s: Mapped[float | None] = mapped_column(Float, nullable=True)
    sim_time_s: Mapped[float | None] = mapped_column(Float, nullable=True)
    cost_usd: Mapped[float] = mapped_column(Float, default=0.0)
    usage: Mapped[dict] = mapped_column(JSON, default=dict)
    nodes: Mapped[dict] = mapped_column(JSON, default=dict)  # per-node durations, retries, recoveries
    # wall seconds per phase of the trial (setup, perception, planning, execution, ...; TrialOutcome.phases_s)
    phases_s: Mapped[dict | None] = mapped_column(JSON, nullable=True)
    trajectory: Mapped[list] = mapped_column(JSON, default=list)  # joint states at the control rate
    artifacts: Mapped[list] = mapped_column(JSON, default=list)  # [{name, kind, camera, path, sha256}] files on disk
    batch_id: Mapped[str | None] = mapped_column(String(255), nullable=True, index=True)
    # [(t_s, qpos)] every 40 ms of simulated time: enough to replay the trial in the 3D view. Loaded on demand.
    scene_states: Mapped[list | None] = mapped_column(JSON, nullable=True, deferred=True)
    # Set by a delete: hidden from every read, restorable until the grace period ends, then purged (0007).
    deleted_at: Mapped[datetime | None] = mapped_column(UTCDateTime(), nullable=True)

    events: Mapped[list[EventRow]] = relationship(
        back_populates="trial", cascade="all, delete-orphan", order_by="EventRow.seq"
    )
    groundings: Mapped[list[GroundingRow]] = relationship(
        back_populates="trial", cascade="all, delete-orphan", order_by="GroundingRow.id"
    )


class EventRow(Base):
    __tablename__ = "events"

    id: Mapped[int] = mapped_column(Integer, primary_key=True, autoincrement=True)
    trial_id: Mapped[str] = mapped_column(ForeignKey("trials.id", ondelete="CASCADE"), index=True)
    seq: Mapped[int] = mapped_column(Integer)
    t: Mapped[float] = mapped_column(Float)  # wall seconds since the trial started
    t_sim: Mapped[float | None] = mapped_column(Float, nullable=True)  # the world's simulated seconds (0009)
    node_path: Mapped[str] = mapped_column(String(256))
    kind: Mapped[str] = mapped_column(String(16))
    detail: Mapped[dict] = mapped_column(JSON, default=dict)

    trial: Mapped[TrialRow] = relationship(back_populates="events")


class GroundingRow(Base):
    """One label resolution: the prompt candidates per camera, the choice, the keypoint."""

    __tablename__ = "groundings"

    id: Mapped[int] = mapped_column(Integer, primary_key=True, autoincrement=True)
    trial_id: Mapped[str] = mapped_column(ForeignKey("trials.id", ondelete="CASCADE"), index=True)
    label: Mapped[str] = mapped_column(String(256))
    record: Mapped[dict] = mapped_column(JSON, default=dict)

    trial: Mapped[TrialRow] = relationship(back_populates="groundings")


class BatchRow(Base):
    """Many trials launched together (a suite or a list of specs)."""

    __tablename__ = "batches"

    id: Mapped[str] = mapped_column(String(255), primary_key=True)
    created_at: Mapped[datetime] = mapped_column(UTCDateTime(), default=utcnow)
    status: Mapped[str] = mapped_column(String(16), default="running")  # running|cancelled|done
    spec: Mapped[dict] = mapped_column(JSON, default=dict)


class PlanLibraryRow(Base):
    """A plan whose trial succeeded, kept as a few-shot example for the LLM planners."""

    __tablename__ = "plan_library"

    id: Mapped[int] = mapped_column(Integer, primary_key=True, autoincrement=True)
    created_at: Mapped[datetime] = mapped_column(UTCDateTime(), default=utcnow)
    instruction: Mapped[str] = mapped_column(Text, index=True)
    plan_text: Mapped[str] = mapped_column(Text)
    scene_summary: Mapped[str] = mapped_column(Text, default="")
    trial_id: Mapped[str | None] = mapped_column(String(255), nullable=True)


class LeaseRow(Base):
    """Who holds a named lease on the store (the console: one server per store), kept alive by its heartbeat."""

    __tablename__ = "leases"

    name: Mapped[str] = mapped_column(String(64), primary_key=True)
    owner: Mapped[str] = mapped_column(String(64))  # a random id per holder
    pid: Mapped[int] = mapped_column(Integer)
    host: Mapped[str] = mapped_column(String(255))
    acquired_at: Mapped[float] = mapped_column(Float)  # epoch seconds
    heartbeat_at: Mapped[float] = mapped_column(Float)  # epoch seconds
