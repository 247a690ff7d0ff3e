"""events carry the world's simulated time (t_sim); trials keep their wall seconds per phase (phases_s)

Revision ID: 0009
Revises: 0008
Create Date: 2026-11-26

Both columns are nullable: events and trials stored before this revision have neither (the console falls back to
its wall-time model for them). Downgrade drops the two columns. On SQLite with ALTER TABLE ... DROP COLUMN
(SQLite >= 3.35), not Alembic's batch rebuild: the rebuild drops and recreates `trials`, and with foreign keys on
that DROP cascades to every event of every trial.
"""

import sqlalchemy as sa
from alembic import op

revision = "0009"
down_revision = "0008"
branch_labels = None
depends_on = None


def upgrade() -> None:
    op.add_column("events", sa.Column("t_sim", sa.Float(), nullable=True))
    op.add_column("trials", sa.Column("phases_s", sa.JSON(), nullable=True))


def downgrade() -> None:
    for table, column in (("trials", "phases_s"), ("events", "t_sim")):
        if op.get_bind().dialect.name == "sqlite":
            op.execute(f"ALTER TABLE {table} DROP COLUMN {column}")
        else:
            op.drop_column(table, column)
