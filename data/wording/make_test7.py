"""Builds the seventh test half, test.yaml, from source_test7.txt (run once; the half is then frozen).

The sixth test half (ids `.zN`) was retired into dev.yaml (README, "Seventh test half") and replaced by this one,
written blind: from the scenes' contents and seed-0 positions, without reading the parser, the grounding code or any
other half of the corpus. Lines are `alias | style | instruction` with the aliases of make_split.py; ids are
`<alias>.<style>.yN`, so they never collide with the ids already in dev.yaml.
"""

from __future__ import annotations

from pathlib import Path

import yaml
from make_split import entries

HERE = Path(__file__).parent


def main() -> None:
    half = entries(HERE / "source_test7.txt", "y")
    (HERE / "test.yaml").write_text(yaml.safe_dump(half, sort_keys=False, width=200))
    print("test", len(half))


if __name__ == "__main__":
    main()
