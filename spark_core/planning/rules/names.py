"""Compound names of the scenes' things whose words would name another kind, or none: said in the one word the
kinds table knows (perception/variants.KINDS), so grounding and the absent-object checks read them as that thing.

"the hot plate" is a stove (a plate is not); "the chest of drawers" a cabinet; "pasta sauce" and "marinara" are
tomato sauce; "canned soup" a soup; a "steel wool pad" steel wool (no sponge). A scene without the thing refuses
the name as absent, as it would the word."""

from __future__ import annotations

import re

_COMPOUNDS: tuple[tuple[str, str], ...] = (
    # an electric hob's one cooking plate: what LIBERO's flat stove is
    (r"\b(?:hot ?plate|hot-plate|cooking plate)(s?)\b", r"stove\1"),
    (r"\b(?:chests? of drawers|drawer (?:unit|chest)|set of drawers)\b", "cabinet"),
    (r"\b(?:pasta|spaghetti) sauce\b|\bmarinara(?: sauce)?\b", "tomato sauce"),
    (r"\bcanned (soup|tomato sauce)\b", r"\1"),
    (r"\bchoc\b\.?", "chocolate"),
    # a scouring pad of steel wool is no sponge: its head noun is the wool
    (r"\b(?:steel|wire) wool(?: pads?| scrubbers?| scourers?| sponges?)?\b|\bbrillo(?: pads?)?\b", "steel wool"),
)


def compound_names(text: str) -> str:
    """`text` (lower case) with each compound name said in the kinds table's word for it."""
    for pattern, word in _COMPOUNDS:
        text = re.sub(pattern, word, text)
    return text
