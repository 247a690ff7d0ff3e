"""Which corpus files the shipped reader was trained on (`train.py collect`), kept apart from the trainer so that
reports can name them without loading torch."""

from __future__ import annotations

import re

# The dev half and probe files already tuned on when the shipped weights were trained; never a test half, never
# `probe22.yaml` (the reader's unseen check then) nor a probe written after it.
DEV_FILES = (
    "data/wording/dev.yaml",
    *(f"data/wording/probe{n}.yaml" for n in (14, 19, 21)),
)


def described() -> str:
    """The training files in words, e.g. "the dev half and probes 14, 19 and 21"."""
    probes = [m.group(1) for p in DEV_FILES if (m := re.search(r"probe(\d+)\.yaml$", p))]
    if not probes:
        return "the dev half"
    listed = probes[0] if len(probes) == 1 else f"{', '.join(probes[:-1])} and {probes[-1]}"
    return f"the dev half and probe{'s' if len(probes) > 1 else ''} {listed}"
