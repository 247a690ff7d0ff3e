"""A benchmark run's per-trial rows on disk: JSON, gzipped when the name ends in `.gz`, so that runs a table is
built from can be committed (data/bench_runs/: a 600-trial LIBERO-PRO run is 1.6 MB as JSON, ~55 kB gzipped)."""

from __future__ import annotations

import gzip
import json
from pathlib import Path
from typing import Any


def write_rows(path: str | Path, rows: Any) -> None:
    """Write `rows` as indented JSON to `path` (gzip-compressed when its name ends in `.gz`)."""
    text = json.dumps(rows, indent=1, default=str)
    path = Path(path)
    if path.suffix == ".gz":
        # mtime 0: the same rows give the same bytes, so a re-written run shows no change in git
        with gzip.GzipFile(path, "wb", mtime=0) as f:
            f.write(text.encode())
    else:
        path.write_text(text)


def read_rows(path: str | Path) -> Any:
    """The JSON in `path` (gunzipped when its name ends in `.gz`). OSError / ValueError as json and gzip raise."""
    path = Path(path)
    if path.suffix == ".gz":
        with gzip.open(path, "rt", encoding="utf-8") as f:
            return json.load(f)
    return json.loads(path.read_text())
