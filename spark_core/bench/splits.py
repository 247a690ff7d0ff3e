"""Development and held-out seeds, fixed once so that reports can say which they used.

LIBERO-PRO ships 50 init states per task; a trial's seed is the init-state index. CaP-Bench and the builtin
suites have no init-state files: a seed draws the start state (robosuite's placement sampler, our scene
builder's object poses). Both use the same ranges:

- `dev`: seeds (init states) 0-9, for developing planners, prompts and perception;
- `heldout`: seeds (init states) 10-49, for the figures we report;
- `all`: 0-49, LIBERO-PRO's full protocol (50 trials per task).
"""

from __future__ import annotations

SPLITS: dict[str, range] = {"dev": range(0, 10), "heldout": range(10, 50), "all": range(0, 50)}


def split_seeds(split: str) -> range:
    """The seeds (init-state indices) of a split; ValueError naming the splits for an unknown one."""
    try:
        return SPLITS[split]
    except KeyError:
        raise ValueError(f"unknown split {split!r}; available: {', '.join(SPLITS)}") from None


def describe(split: str | None, seeds: range) -> str:
    """How a report names its seeds: the split and its range, or the ad-hoc range."""

    def span(r: range) -> str:
        return f"{r.start}-{r.stop - 1}" if len(r) > 1 else f"{r.start}"

    if split is None:
        return f"seeds {span(seeds)} (no named split)"
    whole = split_seeds(split)
    if seeds == whole:
        return f"split {split} (seeds / init states {span(whole)})"
    return f"split {split} (seeds / init states {span(whole)}), of it seeds {span(seeds)}"


def split_of(seeds: range) -> str | None:
    """The named split these exact seeds are, if any."""
    return next((name for name, r in SPLITS.items() if r == seeds), None)


__all__ = ["SPLITS", "describe", "split_of", "split_seeds"]
