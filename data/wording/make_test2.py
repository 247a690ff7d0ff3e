"""Built the second test half from source_test2.txt (run once; the half was then frozen, and later retired into
dev.yaml: README, "Third test half"). It now writes test2.yaml, so a re-run cannot overwrite the current half.

The first test half was retired into dev.yaml (README, "Second test half"). Lines are `alias | style | instruction`
with the aliases of make_split.py; ids are `<alias>.<style>.rN`, so they never collide with the first corpus's ids.
"""

from __future__ import annotations

from pathlib import Path

import yaml
from make_split import entries

HERE = Path(__file__).parent


def main() -> None:
    half = entries(HERE / "source_test2.txt", "r")
    (HERE / "test2.yaml").write_text(yaml.safe_dump(half, sort_keys=False, width=200))
    print("test2", len(half))


if __name__ == "__main__":
    main()
