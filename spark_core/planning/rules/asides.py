"""Asides: parts of a sentence that say how or that the request is over, not what to do with which thing ("..., no
need to be gentle about it", "... and try not to knock it over", "..., that's the target", "- that's all", "...,
keeping it upright").

The order-free reader (reader.py) reads no sentence with a negation in it, since a negation may pick a thing out
("not the red one") or say what to leave be. An aside is a part of the sentence (between commas, dashes, "and",
"but") that names no thing at all: each of its words is a word that names nothing, a verb ("knock", "rush"), or
"it"/"them"; nothing in it singles a thing out ("one", "other", "else", a colour). Such a part is dropped before
reading: its negation is about manner, and what is done, and to what, is said elsewhere. So is a part that names no
thing and says with an "-ing" verb how "it" is handled ("keeping it level")."""

from __future__ import annotations

from collections.abc import Callable

from lemminflect import getAllLemmas

from ...perception.colors import BASE_COLOURS
from ...perception.variants import KIND_OF
from .lexicon import DETERMINERS
from .mentions import ATTRIBUTES
from .things import is_verb

# Words that pick a thing out by what it is not, or that it is another: an aside never holds one.
_SELECTORS = frozenset(
    ["one", "ones", "other", "another", "else", "rest", "instead", "rather", "except", "besides", "apart", "neither"]
    + ["nor", "either", "only", "without", "alone", "than"]
)
# Where a sentence's parts meet.
_JOINS = frozenset([",", "and", "but", "-"])
# What a closing remark says of the request itself ("that's the target", "that's what I'm after", "that's all").
_CLOSING = frozenset(["target", "goal", "aim", "idea", "plan", "job", "task", "what", "all", "everything", "it"])


def aside_positions(tokens: list[str], closed: Callable[[str], bool]) -> set[int]:
    """Token indices of the asides in `tokens` (the reader's tokens): parts that name no thing and either hold a
    negation or close the request ("that is the target"). `closed` says a word names no thing (the reader's)."""
    out: set[int] = set()
    parts: list[list[int]] = [[]]
    for n, t in enumerate(tokens):
        if t in _JOINS:
            parts.append([])
        else:
            parts[-1].append(n)
    if sum(1 for p in parts if p) < 2:
        return out  # the whole sentence: nothing is said elsewhere
    for part in parts:
        words = [tokens[n] for n in part]
        if not words or set(words) & _SELECTORS or set(words) & set(BASE_COLOURS):
            continue
        # how the thing is to be handled, said with an "-ing" verb about it ("..., keeping it flat on the table")
        manner = words[0].endswith("ing") and is_verb(words[0]) and bool(set(words) & {"it", "them"})
        if set(words) & ATTRIBUTES and not manner:
            continue  # "the round one": picks a thing out
        negated = bool(set(words) & {"not", "no", "never", "leave"}) or any(w.endswith("n't") for w in words)
        closing = words[:2] in (["that", "is"], ["this", "is"], ["that", "will"]) and all(
            w in _CLOSING or closed(w) for w in words[2:]
        )
        if not (negated or closing or manner):
            continue
        if all(
            (closing and w in _CLOSING) or (manner and _says_how(w)) or _names_nothing(words, i, closed)
            for i, w in enumerate(words)
        ):
            out |= set(part)
    return out


def _says_how(word: str) -> bool:
    """A word that can say how a thing is kept ("flat", "level", "steady"): one the lexicon knows as an adjective,
    and no kind of thing."""
    return word not in KIND_OF and "ADJ" in getAllLemmas(word)


def _names_nothing(words: list[str], i: int, closed: Callable[[str], bool]) -> bool:
    """The word names no thing here: a word that names none, or a verb not said after a determiner ("to knock",
    not "the block")."""
    w = words[i]
    if w in KIND_OF:
        return False  # a kind of thing, whatever the lexicon says ("pan" only as a verb)
    if w in ("it", "them") or closed(w):
        return True
    before = words[i - 1] if i else ""
    return is_verb(w) and before not in DETERMINERS and before not in ATTRIBUTES
