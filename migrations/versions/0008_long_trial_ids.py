"""trial and batch ids up to 255 characters (a LIBERO-PRO task name alone is up to 108, and ids embed it)

Revision ID: 0008
Revises: 0007
Create Date: 2026-11-26

PostgreSQL enforces VARCHAR lengths (SQLite does not): `spark run liberopro:... --store postgresql+...` made an id
of ~125 characters and failed on the 64-character column. On SQLite this revision changes nothing on disk (the
length is not enforced, and rebuilding every table of a large store for it would be pure cost).
"""

import sqlalchemy as sa
from alembic import op

revision = "0008"
down_revision = "0007"
branch_labels = None
depends_on = None

# (table, column, nullable)
ID_COLUMNS = [
    ("trials", "id", False),
    ("trials", "batch_id", True),
    ("events", "trial_id", False),
    ("groundings", "trial_id", False),
    ("plan_library", "trial_id", True),
    ("batches", "id", False),
]


def _resize(length: int) -> None:
    if op.get_bind().dialect.name == "sqlite":
        return
    for table, column, nullable in ID_COLUMNS:
        op.alter_column(table, column, type_=sa.String(length), existing_nullable=nullable)


def upgrade() -> None:
    _resize(255)


def downgrade() -> None:
    _resize(64)  # fails, naming the value, if a longer id was stored since: nothing is cut silently
