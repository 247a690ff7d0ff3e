"""initial trace store: trials, events, groundings

Revision ID: 0001
Revises:
Create Date: 2026-11-23
"""

import sqlalchemy as sa
from alembic import op

revision = "0001"
down_revision = None
branch_labels = None
depends_on = None


def upgrade() -> None:
    op.create_table(
        "trials",
        sa.Column("id", sa.String(64), primary_key=True),
        sa.Column("created_at", sa.DateTime(timezone=True), nullable=False),
        sa.Column("status", sa.String(16), nullable=False),
        sa.Column("instruction", sa.Text, nullable=False),
        sa.Column("task", sa.String(128), nullable=False),
        sa.Column("seed", sa.Integer, nullable=False),
        sa.Column("planner", sa.String(64), nullable=False),
        sa.Column("resolver", sa.String(128), nullable=False),
        sa.Column("protocol", sa.JSON, nullable=False),
        sa.Column("plan_text", sa.Text, nullable=False),
        sa.Column("plan_tree", sa.JSON, nullable=True),
        sa.Column("outcome", sa.String(16), nullable=False),
        sa.Column("success", sa.Boolean, nullable=True),
        sa.Column("failure", sa.String(32), nullable=True),
        sa.Column("failed_node", sa.String(256), nullable=True),
        sa.Column("reason", sa.Text, nullable=False),
        sa.Column("wall_time_s", sa.Float, nullable=True),
        sa.Column("sim_time_s", sa.Float, nullable=True),
        sa.Column("cost_usd", sa.Float, nullable=False),
        sa.Column("usage", sa.JSON, nullable=False),
        sa.Column("nodes", sa.JSON, nullable=False),
        sa.Column("trajectory", sa.JSON, nullable=False),
    )
    for col in ("created_at", "status", "task", "outcome", "success"):
        op.create_index(f"ix_trials_{col}", "trials", [col])
    op.create_table(
        "events",
        sa.Column("id", sa.Integer, primary_key=True, autoincrement=True),
        sa.Column("trial_id", sa.String(64), sa.ForeignKey("trials.id", ondelete="CASCADE"), nullable=False),
        sa.Column("seq", sa.Integer, nullable=False),
        sa.Column("t", sa.Float, nullable=False),
        sa.Column("node_path", sa.String(256), nullable=False),
        sa.Column("kind", sa.String(16), nullable=False),
        sa.Column("detail", sa.JSON, nullable=False),
    )
    op.create_index("ix_events_trial_id", "events", ["trial_id"])
    op.create_table(
        "groundings",
        sa.Column("id", sa.Integer, primary_key=True, autoincrement=True),
        sa.Column("trial_id", sa.String(64), sa.ForeignKey("trials.id", ondelete="CASCADE"), nullable=False),
        sa.Column("label", sa.String(256), nullable=False),
        sa.Column("record", sa.JSON, nullable=False),
    )
    op.create_index("ix_groundings_trial_id", "groundings", ["trial_id"])


def downgrade() -> None:
    op.drop_table("groundings")
    op.drop_table("events")
    op.drop_table("trials")
