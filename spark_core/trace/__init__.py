"""The trace store: every trial as a labeled record (SQLAlchemy 2 on SQLite or PostgreSQL, Alembic migrations)."""

from .models import Base, EventRow, GroundingRow, TrialRow
from .store import TraceStore

__all__ = ["Base", "EventRow", "GroundingRow", "TraceStore", "TrialRow"]
