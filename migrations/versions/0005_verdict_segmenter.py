"""one verdict per trial (the trial pipeline's closed set); the perception backend is called `segmenter`

Revision ID: 0005
Revises: 0004
Create Date: 2026-11-26
"""

import sqlalchemy as sa
from alembic import op

revision = "0005"
down_revision = "0004"
branch_labels = None
depends_on = None

# Older rows get the verdict their stored fields imply (same rule as spark_core.trial.Verdict).
BACKFILL = """
UPDATE trials SET verdict = CASE
  WHEN status = 'interrupted' THEN 'interrupted'
  WHEN status IN ('queued', 'running') THEN NULL
  WHEN success THEN 'success'
  WHEN outcome = 'aborted' THEN 'aborted'
  WHEN failure = 'planner' THEN 'planner_error'
  WHEN failure IN ('worker', 'internal') THEN 'crashed'
  WHEN outcome = 'success' THEN 'task_unmet'
  ELSE 'tree_failed' END
"""


def upgrade() -> None:
    with op.batch_alter_table("trials") as batch:
        batch.add_column(sa.Column("verdict", sa.String(16), nullable=True))
        batch.alter_column("resolver", new_column_name="segmenter", existing_type=sa.String(128))
        batch.create_index("ix_trials_verdict", ["verdict"])
    op.execute(BACKFILL)


def downgrade() -> None:
    with op.batch_alter_table("trials") as batch:
        batch.drop_index("ix_trials_verdict")
        batch.alter_column("segmenter", new_column_name="resolver", existing_type=sa.String(128))
        batch.drop_column("verdict")
