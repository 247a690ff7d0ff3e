"""scene states for replay (qpos every 40 ms of simulated time); the plan library moves into the store

Revision ID: 0004
Revises: 0003
Create Date: 2026-11-24
"""

import sqlalchemy as sa
from alembic import op

revision = "0004"
down_revision = "0003"
branch_labels = None
depends_on = None


def upgrade() -> None:
    with op.batch_alter_table("trials") as batch:
        batch.add_column(sa.Column("scene_states", sa.JSON, nullable=True))
    op.create_table(
        "plan_library",
        sa.Column("id", sa.Integer, primary_key=True, autoincrement=True),
        sa.Column("created_at", sa.DateTime(timezone=True), nullable=False),
        sa.Column("instruction", sa.Text, nullable=False),
        sa.Column("plan_text", sa.Text, nullable=False),
        sa.Column("scene_summary", sa.Text, nullable=False),
        sa.Column("trial_id", sa.String(64), nullable=True),
    )
    op.create_index("ix_plan_library_instruction", "plan_library", ["instruction"])


def downgrade() -> None:
    op.drop_index("ix_plan_library_instruction", "plan_library")
    op.drop_table("plan_library")
    with op.batch_alter_table("trials") as batch:
        batch.drop_column("scene_states")
