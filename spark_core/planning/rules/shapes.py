"""Goals stated by how a container ends up rather than by what moves: "fill the bowl with the beads", "the bowl full
of beads", "bowl filled with beads, mug empty". Each says the contents go into the container said to be full, out
of the one said to be empty; the order-free reader (reader.py) reads them as said that way ("the beads into the
bowl, out of the mug"), and every thing named is still one the scene must hold."""

from __future__ import annotations

import re

_NP = r"(?:(?:the|a|an|that|this) )?[a-z][a-z ]*?"
_END = r"(?=\s*(?:[,;.!?]|$| and\b| from\b| out of\b))"  # where the contents' phrase ends

_SHAPES: tuple[tuple[re.Pattern[str], str], ...] = (
    # "fill (up) the bowl with the beads": the contents into the container
    (
        re.compile(rf"\bfill(?: up)? ({_NP})(?: up)? with ({_NP}){_END}"),
        r"\2 into \1",
    ),
    # "the bowl (should be / is / to be / ends up) full of beads", "... filled with beads"
    (
        re.compile(
            rf"\b({_NP}) (?:(?:should|must|needs to|has to|ought to) (?:be|end up) |is |to be |ends up |left )?"
            rf"(?:full of|filled with|filled up with) ({_NP}){_END}"
        ),
        r"\2 into \1",
    ),
    # "..., the mug empty", "... and the mug (left / should be) empty": where they come out of
    (
        re.compile(
            rf"(,|\band\b)\s*({_NP}) (?:(?:should|must|needs to|has to|ought to) (?:be|end up) |is |left |ends up )?"
            r"(?:empty|emptied)\s*$"
        ),
        r"\1 out of \2",
    ),
)


def as_moved(instruction: str) -> str | None:
    """The instruction with each such goal said as the contents' move ("fill the bowl with beads" -> "beads into
    the bowl"); None when it states none."""
    text = instruction.lower().strip().rstrip(".!")
    out = text
    for pattern, repl in _SHAPES:
        out = pattern.sub(repl, out)
    return out if out != text else None
