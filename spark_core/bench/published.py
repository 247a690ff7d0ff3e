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
        lines.append(f"| {t} | {pct(ours)} | {pub['SPARK'] + ' %' if pub['SPARK'] else '-'} | "
                     f"{pub['CaP-X'] + ' %' if pub['CaP-X'] else '-'} |")
    return "\n".join(lines)
