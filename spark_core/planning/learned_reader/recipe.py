"""Which corpus files the shipped reader was trained on (`train.py collect`), kept apart from the trainer so that
reports can name them without loading torch."""

from __future__ import annotations

import re

# The dev half and probe files already tuned on when the shipped weights were trained (round 30); never a test
# half, never a probe written after probe35 (probes 36-38 were read after the examples were collected; probes 39 and
# 40 are the reader's unseen checks).
DEV_FILES = (
    "data/wording/dev.yaml",
    *(f"data/wording/probe{n}.yaml" for n in (14, 19, *range(21, 36))),
)


def described() -> str:
    """The training files in words, e.g. "the dev half and probes 14, 19 and 21-35" (a run of three or more probes
    is a range)."""
    probes = [int(m.group(1)) for p in DEV_FILES if (m := re.search(r"probe(\d+)\.yaml$", p))]
    if not probes:
        return "the dev half"
    runs: list[list[int]] = []
    for n in probes:
        if runs and n == runs[-1][-1] + 1:
            runs[-1].append(n)
        else:
            runs.append([n])
    parts = [f"{r[0]}-{r[-1]}" if len(r) >= 3 else ", ".join(map(str, r)) for r in runs]
    words = ", ".join(parts).split(", ")
    listed = words[0] if len(words) == 1 else f"{', '.join(words[:-1])} and {words[-1]}"
    plural = len(probes) > 1
    return f"the dev half and probe{'s' if plural else ''} {listed}"
