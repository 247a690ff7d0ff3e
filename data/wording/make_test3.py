"""Builds the third test half, test.yaml, from source_test3.txt (run once; the half is then frozen).

The second test half (ids `.rN`) was retired into dev.yaml and test.yaml is overwritten (README, "Third test half").
Lines are `alias | style | instruction` with the aliases of make_split.py; ids are `<alias>.<style>.tN`, so they never
collide with the ids already in dev.yaml.
"""

from __future__ import annotations

from pathlib import Path

import yaml
from make_split import REFUSALS, task_of

HERE = Path(__file__).parent


def main() -> None:
    entries: list[dict] = []
    counts: dict[str, int] = {}
    for line in (HERE / "source_test3.txt").read_text().splitlines():
        if not line.strip() or line.startswith("#"):
            continue
        alias, style, instruction = (p.strip() for p in line.split("|", 2))
        suite, task = task_of(alias)
        n = counts[f"{alias}.{style}"] = counts.get(f"{alias}.{style}", 0) + 1
        entries.append(
            {
                "id": f"{alias}.{style}.t{n}",
                "style": style,
                "suite": suite,
                "task": task,
                "expect": f"refuse:{style}" if style in REFUSALS else "goal",
                "instruction": instruction,
            }
        )
    (HERE / "test.yaml").write_text(yaml.safe_dump(entries, sort_keys=False, width=200))
    print("test", len(entries))


if __name__ == "__main__":
    main()
