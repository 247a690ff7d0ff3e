"""Published results the suites are measured against (success %, as reported): the SPARK paper and CaP-X."""

from __future__ import annotations

from .report import pct

# task -> {source: success %}. CaP-X two-arm figures are read off its plot (approximate).
PUBLISHED: dict[str, dict[str, str]] = {
    "Lift": {"SPARK": "100", "CaP-X": ""},
    "Stack": {"SPARK": "97", "CaP-X": ""},
    "CubeRestack": {"SPARK": "100", "CaP-X": ""},
    "Wipe": {"SPARK": "60", "CaP-X": ""},
    "NutAssemblySquare": {"SPARK": "0", "CaP-X": ""},
    "TwoArmLift": {"SPARK": "63", "CaP-X": "~70"},
    "TwoArmHandover": {"SPARK": "24", "CaP-X": "~30"},
}


def comparison_table(rows: list[dict]) -> str:
    """Ours next to the published figures, for the tasks that have them ('' when there are none)."""
    tasks = [t for t in dict.fromkeys(r["task"] for r in rows) if t in PUBLISHED]
    if not tasks:
        return ""
    lines = ["| task | ours | SPARK (paper) | CaP-X (paper) |", "|---|---|---|---|"]
    for t in tasks:
        rs = [r for r in rows if r["task"] == t]
        ours = sum(r["success"] for r in rs) / len(rs)
        pub = PUBLISHED[t]
        lines.append(
            f"| {t} | {pct(ours)} | {pub['SPARK'] + ' %' if pub['SPARK'] else '-'} | "
            f"{pub['CaP-X'] + ' %' if pub['CaP-X'] else '-'} |"
        )
    return "\n".join(lines)


# LIBERO-PRO (SPARK paper, success %): per suite, position perturbation (the `_swap` cells) and task perturbation.
LIBEROPRO_CELLS: dict[str, str] = {
    "libero_object_swap": "43.4",
    "libero_object_task": "36.4",
    "libero_goal_swap": "40.0",
    "libero_goal_task": "14.0",
    "libero_spatial_swap": "56.0",
    "libero_spatial_task": "72.4",
}
LIBEROPRO_MEAN = "43.7"


def cell_table(rows: list[dict]) -> str:
    """LIBERO-PRO: success per cell (tasks named '<cell>:<task>') next to the paper's, and the mean over cells."""
    cells = [c for c in LIBEROPRO_CELLS if any(r["task"].startswith(c + ":") for r in rows)]
    if not cells:
        return ""
    lines = ["| cell | ours | trials | SPARK (paper) |", "|---|---|---|---|"]
    rates = []
    for c in cells:
        rs = [r for r in rows if r["task"].startswith(c + ":")]
        rate = sum(r["success"] for r in rs) / len(rs)
        rates.append(rate)
        lines.append(f"| {c} | {pct(rate)} | {len(rs)} | {LIBEROPRO_CELLS[c]} % |")
    lines.append(f"| **mean over cells** | **{pct(sum(rates) / len(rates))}** | {len(rows)} | {LIBEROPRO_MEAN} % |")
    return "\n".join(lines)
