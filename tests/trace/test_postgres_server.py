"""The throwaway PostgreSQL server the store tests use: skipped only when the binaries are missing, saying why."""

from pathlib import Path

import pytest

from tests.trace import postgres_server


def test_missing_binaries_are_the_one_reason_to_skip(monkeypatch):
    monkeypatch.setattr(postgres_server.shutil, "which", lambda name: None)
    monkeypatch.setattr(postgres_server.glob, "glob", lambda pattern: [])
    with pytest.raises(postgres_server.PostgresUnavailable, match="install Debian's `postgresql`"):
        postgres_server.PostgresServer()


def test_the_server_runs_as_a_non_root_user_and_serves_fresh_databases(postgres_server):
    from sqlalchemy import create_engine, text

    a, b = postgres_server.new_database(), postgres_server.new_database()
    assert a != b and a.startswith("postgresql+psycopg://spark@127.0.0.1:")
    engine = create_engine(a)
    try:
        with engine.connect() as c:
            owner = c.execute(text("select usename from pg_stat_activity where pid = pg_backend_pid()")).scalar()
            tables = c.execute(text("select count(*) from information_schema.tables where table_schema='public'"))
            assert owner == "spark" and tables.scalar() == 0
    finally:
        engine.dispose()
    pid = int((postgres_server.data / "postmaster.pid").read_text().split()[0])
    status = Path(f"/proc/{pid}/status").read_text().splitlines()
    uid = next(line for line in status if line.startswith("Uid:")).split()[1]
    assert uid != "0"  # PostgreSQL refuses root: as root the tests run it as another user
