"""Slips of the keyboard ("the stvoe", "teh basket", "salad dresing", "creamcheese"): a word the English lexicon does
not know, one keystroke away from exactly one word the planner reads or the scene's things are called by, is read
as that word; a word the lexicon does not know that is two of the scene's words run together is read as both.

Only words unknown to the lexicon are touched, so a real word that names something the scene lacks ("the
grapefruit") is never turned into one it holds; and a slip is read only as a word the planner itself knows or a
word of a thing perception lists in this scene (its inventory), never guessed from a wider dictionary."""

from __future__ import annotations

import re
from functools import lru_cache

from lemminflect import getAllLemmas

from ...perception.colors import BASE_COLOURS
from ...perception.variants import KIND_OF
from .lexicon import DETERMINERS, FILLERS
from .mentions import ABSTRACT, _closed_words
from .things import NOT_THINGS

_MIN = 3  # shorter words are too close to too many others


def _one_slip(a: str, b: str) -> bool:
    """One keystroke apart: a letter added, dropped or changed, or two neighbours swapped."""
    if a == b or abs(len(a) - len(b)) > 1:
        return False
    if len(a) == len(b):
        diff = [i for i in range(len(a)) if a[i] != b[i]]
        if len(diff) == 1:
            return True
        i, j = diff[0], diff[-1]
        return len(diff) == 2 and j == i + 1 and a[i] == b[j] and a[j] == b[i]
    short, long = (a, b) if len(a) < len(b) else (b, a)
    return any(long[:i] + long[i + 1 :] == short for i in range(len(long)))


@lru_cache(maxsize=1)
def _planner_words() -> frozenset[str]:
    """Every word the planner reads: its verbs, prepositions, fillers and closed words, the interjections and
    shorthand it knows ("sec", "atop", "pls"), the kinds of things and the colours."""
    fillers = {w for f in FILLERS for w in f.split()}
    words = _closed_words() | set(DETERMINERS) | set(KIND_OF) | set(BASE_COLOURS) | ABSTRACT | NOT_THINGS | fillers
    return frozenset(w for w in words if w.isalpha())


def _scene_words(inventory: tuple[str, ...]) -> frozenset[str]:
    words = {w for n in inventory for w in re.sub(r"\s*\(\d+\)$", "", n).lower().replace("_", " ").split()}
    return frozenset(w for w in words if w.isalpha())


def _fix(word: str, known: frozenset[str], scene: frozenset[str]) -> str | None:
    if len(word) < _MIN or word in known or getAllLemmas(word):
        return None
    near = {k for k in known if len(k) >= _MIN and _one_slip(word, k)}
    if len(near) == 1:
        return next(iter(near))
    splits = [
        f"{word[:i]} {word[i:]}" for i in range(_MIN, len(word) - _MIN + 1) if word[:i] in scene and word[i:] in scene
    ]
    return splits[0] if len(splits) == 1 else None


def corrected(instruction: str, inventory: tuple[str, ...] = ()) -> str:
    """`instruction` with each slip read as the word it misses; unchanged when it has none."""
    scene = _scene_words(inventory)
    known = _planner_words() | scene

    def fix(m: re.Match) -> str:
        word = m.group(0)
        better = _fix(word.lower(), known, scene)
        return better if better is not None else word

    return re.sub(r"(?<!['\w])[A-Za-z]+(?!['\w])", fix, instruction)
