"""Alternative text prompts for an object label (adaptive self-consistency), derived deterministically from
the label's words with a synonym table. The planning layer may supply its own variants instead."""

from __future__ import annotations

SYNONYMS: dict[str, tuple[str, ...]] = {
    "block": ("cube", "wooden block"),
    "cube": ("block", "box"),
    "mug": ("cup", "coffee mug"),
    "cup": ("mug", "drinking cup"),
    "plate": ("dish", "round plate"),
    "bowl": ("round bowl", "dish"),
    "tray": ("plastic tray", "flat tray"),
    "basket": ("wicker basket", "bin"),
    "sponge": ("kitchen sponge", "scrubbing pad"),
    "bottle": ("plastic bottle", "flask"),
    "knob": ("dial", "control knob"),
    "handle": ("pull handle", "grip"),
    "drawer": ("cabinet drawer", "sliding drawer"),
    "stove": ("cooktop", "burner"),
    "cooktop": ("stove", "electric stove"),
    "hob": ("stove", "cooktop"),
    "cupboard": ("cabinet", "wooden cabinet"),
    "dish": ("plate", "round dish"),
    "zone": ("area", "target area"),
    "peg": ("rod", "stick"),
    "nut": ("square nut", "metal nut"),
    "brush": ("scrub brush", "bristle brush"),
    "area": ("zone", "target area"),
    "bead": ("small ball", "marble"),
    "cabinet": ("cupboard", "wooden cabinet"),
}


def prompt_variants(label: str, k: int = 3) -> list[str]:
    """`k` alternative prompts for `label` (never the label itself), e.g. red block -> red cube, red wooden block."""
    words = label.split()
    out: list[str] = []
    for i in range(len(words) - 1, -1, -1):
        for syn in SYNONYMS.get(words[i], ()):
            cand = " ".join(words[:i] + [syn] + words[i + 1 :])
            if cand != label and cand not in out:
                out.append(cand)
    if len(words) > 1 and words[-1] not in out:  # the bare noun as a last resort ("the bowl")
        out.append(f"the {words[-1]}")
    return out[:k]
