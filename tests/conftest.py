import os
import sys
from pathlib import Path

os.environ.setdefault("MUJOCO_GL", "egl")
os.environ.setdefault("HF_HUB_OFFLINE", "1")
# One Ray token-auth mode for the whole session: Ray caches its mode per process, and a test cluster started with
# auth off followed by a local ray.init() that turns it on (a ~/.ray/auth_token on the machine) fails to connect.
os.environ.setdefault("RAY_AUTH_MODE", "disabled")
ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

import pytest  # noqa: E402


def pytest_collection_modifyitems(config, items):
    """Slow suites run in full with SPARK_SLOW=1 (`make test-all`); CI runs the sampled subset."""
    if os.environ.get("SPARK_SLOW") == "1":
        return
    skip = pytest.mark.skip(reason="slow: run with SPARK_SLOW=1 (make test-all)")
    for item in items:
        if "slow" in item.keywords:
            item.add_marker(skip)


@pytest.fixture(scope="session")
def postgres_server():
    """A real PostgreSQL server for the session (tests/trace/postgres_server.py); skipped, saying why, only
    when the server binaries are not installed."""
    from tests.trace.postgres_server import PostgresServer, PostgresUnavailable

    try:
        server = PostgresServer()
    except PostgresUnavailable as e:
        pytest.skip(str(e))
    try:
        server.start()
    except BaseException:
        server.stop()
        raise
    yield server
    server.stop()


@pytest.fixture(params=["sqlite", "postgresql"])
def store_url(request, tmp_path):
    """A fresh empty trace store URL on each backend: a SQLite file, and a new database on the PostgreSQL server."""
    if request.param == "sqlite":
        return f"sqlite:///{tmp_path / 'trace.db'}"
    return request.getfixturevalue("postgres_server").new_database()
