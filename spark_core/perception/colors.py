"""Colour words: synonyms mapped to base colour names, so "crimson cube" and "red block" agree on colour.

Sentence embeddings barely separate colour synonyms when the rest of the phrase matches several objects
(three "small wooden cube blocks"); grounding therefore normalises colour words and checks colour agreement
explicitly.
"""

from __future__ import annotations

BASE_COLOURS = ("red", "green", "blue", "yellow", "white", "black", "brown", "grey", "orange", "purple", "pink")
SYNONYMS = {
    "crimson": "red",
    "scarlet": "red",
    "ruby": "red",
    "cherry": "red",
    "maroon": "red",
    "emerald": "green",
    "lime": "green",
    "olive": "green",
    "jade": "green",
    "navy": "blue",
    "azure": "blue",
    "cobalt": "blue",
    "cyan": "blue",
    "sapphire": "blue",
    "teal": "blue",
    "golden": "yellow",
    "gold": "yellow",
    "lemon": "yellow",
    "mustard": "yellow",
    "ivory": "white",
    "cream": "white",
    "ebony": "black",
    "dark": "black",
    "gray": "grey",
    "silver": "grey",
    "tan": "brown",
    "wooden": "brown",
    "beige": "brown",
    "violet": "purple",
    "magenta": "pink",
}


def normalise_colours(text: str) -> str:
    return " ".join(SYNONYMS.get(w, w) for w in text.lower().split())


def colours_in(text: str) -> set[str]:
    return {w for w in normalise_colours(text).split() if w in BASE_COLOURS}
