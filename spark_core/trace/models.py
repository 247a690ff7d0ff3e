"""SQLAlchemy models of the trace store. Schema changes go through Alembic (migrations/versions)."""

from __future__ import annotations

from datetime import UTC, datetime

from sqlalchemy import JSON, Boolean, DateTime, Float, ForeignKey, Integer, String, Text
from sqlalchemy.orm import DeclarativeBase, Mapped, mapped_column, relationship


def utcnow() -> datetime:
    return datetime.now(UTC)


class Base(DeclarativeBase):
    pass


class TrialRow(Base):
    """One trial: what was asked, with which backends, the plan, and how it ended."""

    __tablename__ = "trials"

    id: Mapped[str] = mapped_column(String(255), primary_key=True)
    created_at: Mapped[datetime] = mapped_column(DateTime(timezone=True), default=utcnow, index=True)
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
    deleted_at: Mapped[datetime | None] = mapped_column(DateTime(timezone=True), nullable=True)

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
    created_at: Mapped[datetime] = mapped_column(DateTime(timezone=True), default=utcnow)
    status: Mapped[str] = mapped_column(String(16), default="running")  # running|cancelled|done
    spec: Mapped[dict] = mapped_column(JSON, default=dict)


class PlanLibraryRow(Base):
    """A plan whose trial succeeded, kept as a few-shot example for the LLM planners."""

    __tablename__ = "plan_library"

    id: Mapped[int] = mapped_column(Integer, primary_key=True, autoincrement=True)
    created_at: Mapped[datetime] = mapped_column(DateTime(timezone=True), default=utcnow)
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
