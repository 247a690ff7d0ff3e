"""soft deletion (trials.deleted_at, in the trial list's indexes) and the console lease (one server per store)

Revision ID: 0007
Revises: 0006
Create Date: 2026-11-27
"""

import sqlalchemy as sa
from alembic import op

revision = "0007"
down_revision = "0006"
branch_labels = None
depends_on = None

# 0006's indexes with deleted_at last: every read filters `deleted_at IS NULL`, and the page's ids still come from
# the index alone (SQLite reads a table row per entry to test a column the index lacks, even for a partial index).
LIST_INDEXES = [
    ("ix_trials_created_at_id", ["created_at", "id"]),
    ("ix_trials_task_created_at", ["task", "created_at", "id"]),
    ("ix_trials_status_created_at", ["status", "created_at", "id"]),
    ("ix_trials_success_created_at", ["success", "created_at", "id"]),
]


def upgrade() -> None:
    op.add_column("trials", sa.Column("deleted_at", sa.DateTime(timezone=True), nullable=True))
    for name, columns in LIST_INDEXES:
        op.drop_index(name, "trials")
        op.create_index(name, "trials", [*columns, "deleted_at"])
    op.create_table(
        "leases",
        sa.Column("name", sa.String(64), primary_key=True),
        sa.Column("owner", sa.String(64), nullable=False),
        sa.Column("pid", sa.Integer, nullable=False),
        sa.Column("host", sa.String(255), nullable=False),
        sa.Column("acquired_at", sa.Float, nullable=False),  # epoch seconds
        sa.Column("heartbeat_at", sa.Float, nullable=False),
    )


def downgrade() -> None:
    op.drop_table("leases")
    for name, columns in LIST_INDEXES:
        op.drop_index(name, "trials")
        op.create_index(name, "trials", columns)
    with op.batch_alter_table("trials") as batch:
        batch.drop_column("deleted_at")
