"""Text an operator submits (labels, instructions, plans, names) must run as the console shows it.

Bidi controls (U+202A-U+202E, U+2066-U+2069) reorder what a page displays, and zero-width and other invisible
format characters (Unicode category Cf: U+200B-U+200F, U+2060-U+2064, U+FEFF, soft hyphen, tags ...) or control
characters (Cc, but tab, newline and carriage return) do not show at all: the console would show one text while
the planner, the perception prompts and the trace store get another. Such text is refused, naming the field,
the character and where it is.
"""

from __future__ import annotations

import unicodedata
from typing import Annotated, Any

from pydantic import BeforeValidator
from pydantic_core import PydanticCustomError

_LAYOUT = frozenset("\t\n\r")  # controls that show as what they are


def hidden_character(text: str, *, leading_bom: bool = False) -> str | None:
    """Where the first character that displays differently than it reads is, and which it is; None if there is
    none. `leading_bom`: a U+FEFF first character is a byte-order mark (a pasted file's), not hidden text."""
    for i, ch in enumerate(text):
        if i == 0 and leading_bom and ch == "\ufeff":
            continue
        category = unicodedata.category(ch)
        if category == "Cf" or (category == "Cc" and ch not in _LAYOUT):
            line = text.count("\n", 0, i) + 1
            column = i - (text.rfind("\n", 0, i) + 1) + 1
            where = f"line {line}, column {column}" if "\n" in text else f"character {i + 1}"
            name = unicodedata.name(ch, "a control character")
            return (
                f"{where}: invisible character U+{ord(ch):04X} ({name}); bidi controls, zero-width and other "
                "invisible format or control characters are refused (the console would show a different text "
                "than the one that runs)"
            )
    return None


# Checked before the str validation, so that the field's own constraints (max_length) still apply to a plain str
# and say so in their own words; anything not a str is left to that validation.


def _visible(value: Any) -> Any:
    problem = hidden_character(value) if isinstance(value, str) else None
    if problem is not None:
        raise PydanticCustomError("invisible_character", problem)
    return value


def _visible_plan(value: Any) -> Any:
    problem = hidden_character(value, leading_bom=True) if isinstance(value, str) else None
    if problem is not None:
        raise PydanticCustomError("invisible_character", problem)
    return value


VISIBLE = BeforeValidator(_visible)
"""A label, instruction or name: shown as it runs. Put it after a Field(max_length=...) in Annotated[str, ...]
so that the length is checked as a string's (a validator before the constraint turns it into a generic one)."""

VISIBLE_PLAN = BeforeValidator(_visible_plan)
"""Plan text (several lines; a leading byte-order mark is allowed, the grammar drops it)."""

Visible = Annotated[str, VISIBLE]
"""A required label or name; its Field(max_length=...) can stand beside it."""
