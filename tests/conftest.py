import os
import sys
from pathlib import Path

os.environ.setdefault("MUJOCO_GL", "egl")
os.environ.setdefault("HF_HUB_OFFLINE", "1")
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
