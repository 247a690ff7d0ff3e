"""indexes that cover the trial list's order (newest first, id breaking ties) with and without its usual filters

Revision ID: 0006
Revises: 0005
Create Date: 2026-11-26
"""

from alembic import op

revision = "0006"
down_revision = "0005"
branch_labels = None
depends_on = None

# (name, columns): the page's ids come from the index alone, with no table rows read and no sort.
INDEXES = [
    ("ix_trials_created_at_id", ["created_at", "id"]),
    ("ix_trials_task_created_at", ["task", "created_at", "id"]),
    ("ix_trials_status_created_at", ["status", "created_at", "id"]),
    ("ix_trials_success_created_at", ["success", "created_at", "id"]),
]


def upgrade() -> None:
    for name, columns in INDEXES:
        op.create_index(name, "trials", columns)


def downgrade() -> None:
    for name, _ in reversed(INDEXES):
        op.drop_index(name, "trials")
