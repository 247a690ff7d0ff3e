"""The front end's own unit tests (web/tests/*.test.ts: plan line paths, plan diff, the workspace's clock and tree
state), run by node's test runner through `npm test`."""

import shutil
import subprocess
from pathlib import Path

import pytest

WEB = Path(__file__).resolve().parents[2] / "web"


@pytest.mark.skipif(not (WEB / "node_modules" / "esbuild").is_dir(), reason="npm ci not run (make install does it)")
def test_front_end_unit_tests_pass():
    r = subprocess.run([shutil.which("npm") or "npm", "test"], cwd=WEB, capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, r.stdout[-4000:] + r.stderr[-2000:]
    assert "# fail 0" in r.stdout
