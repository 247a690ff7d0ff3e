"""A throwaway PostgreSQL server for tests: initdb + pg_ctl in a temporary directory, on a free loopback port.

PostgreSQL refuses to run as root, and the tests may run as root (CI does): then the server runs as the
`postgres` user Debian's package creates (or `nobody`), through `runuser`. Everything lives in one temp
directory owned by that user; `stop()` kills the server and removes it."""

from __future__ import annotations

import glob
import os
import pwd
import shutil
import socket
import subprocess
import tempfile
import uuid
from pathlib import Path


class PostgresUnavailable(RuntimeError):
    """The server binaries are not installed (the tests skip with this message)."""


class PostgresFailed(RuntimeError):
    """The binaries are there but the server could not be set up: a failure, never a skip."""


def _bin_dir() -> Path:
    initdb = shutil.which("initdb")
    if initdb:
        return Path(initdb).resolve().parent
    found = sorted(glob.glob("/usr/lib/postgresql/*/bin/initdb"))  # Debian keeps them off PATH
    if not found:
        raise PostgresUnavailable(
            "PostgreSQL server binaries (initdb, pg_ctl) not found: install Debian's `postgresql` (scripts/apt-deps.sh)"
        )
    return Path(found[-1]).parent


def _run_as() -> list[str]:
    """The command prefix that runs a server binary as a non-root user ([] when we are not root)."""
    if os.geteuid() != 0:
        return []
    if not shutil.which("runuser"):
        raise PostgresFailed("running as root and `runuser` is missing: PostgreSQL will not run as root")
    for user in ("postgres", "nobody"):
        try:
            pwd.getpwnam(user)
        except KeyError:
            continue
        return ["runuser", "-u", user, "--"]
    raise PostgresFailed("running as root and there is no `postgres` or `nobody` user to run PostgreSQL as")


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


class PostgresServer:
    def __init__(self) -> None:
        self.bin = _bin_dir()
        self.prefix = _run_as()
        self.dir = Path(tempfile.mkdtemp(prefix="spark-pg-"))
        if self.prefix:
            user = self.prefix[2]
            entry = pwd.getpwnam(user)
            os.chown(self.dir, entry.pw_uid, entry.pw_gid)
        self.data = self.dir / "data"
        self.port = _free_port()
        self.started = False

    def _run(self, *args: str) -> None:
        done = subprocess.run([*self.prefix, *args], capture_output=True, text=True, timeout=60)
        if done.returncode != 0:
            raise PostgresFailed(f"{Path(args[0]).name} failed: {done.stderr.strip() or done.stdout.strip()}")

    def start(self) -> PostgresServer:
        # trust auth on loopback only, fsync off: a disposable test server
        self._run(str(self.bin / "initdb"), "-D", str(self.data), "-U", "spark", "-A", "trust", "-E", "UTF8", "-N")
        options = f"-p {self.port} -k {self.dir} -c listen_addresses=127.0.0.1 -c fsync=off -c max_connections=200"
        log = str(self.dir / "log")
        self._run(str(self.bin / "pg_ctl"), "-D", str(self.data), "-o", options, "-l", log, "-w", "start")
        self.started = True
        return self

    def url(self, database: str = "postgres") -> str:
        return f"postgresql+psycopg://spark@127.0.0.1:{self.port}/{database}"

    def new_database(self) -> str:
        """A fresh empty database on the server; its SQLAlchemy URL."""
        from sqlalchemy import create_engine, text

        name = f"t_{uuid.uuid4().hex[:12]}"
        engine = create_engine(self.url(), isolation_level="AUTOCOMMIT")
        try:
            with engine.connect() as c:
                c.execute(text(f'CREATE DATABASE "{name}"'))
        finally:
            engine.dispose()
        return self.url(name)

    def stop(self) -> None:
        if self.started:
            subprocess.run(
                [*self.prefix, str(self.bin / "pg_ctl"), "-D", str(self.data), "-m", "immediate", "-w", "stop"],
                capture_output=True,
                timeout=60,
            )
            self.started = False
        shutil.rmtree(self.dir, ignore_errors=True)
