"""Builds the third test half, test.yaml, from source_test3.txt (run once; the half is then frozen).

The second test half (ids `.rN`) was retired into dev.yaml (README, "Third test half"). This half was itself retired
into dev.yaml (README, "Fourth test half"), so the script now writes test3.yaml, never the current test.yaml.
Lines are `alias | style | instruction` with the aliases of make_split.py; ids are `<alias>.<style>.tN`, so they never
collide with the ids already in dev.yaml.
"""

from __future__ import annotations

from pathlib import Path

import yaml
from make_split import entries

HERE = Path(__file__).parent


def main() -> None:
    half = entries(HERE / "source_test3.txt", "t")
    (HERE / "test3.yaml").write_text(yaml.safe_dump(half, sort_keys=False, width=200))
    print("test3", len(half))


if __name__ == "__main__":
    main()
