"""Slips of the keyboard ("the stvoe", "teh basket", "salad dresing", "creamcheese"): a word the English lexicon does
not know, one keystroke away from exactly one word the planner reads or the scene's things are called by, is read
as that word (of several such words, the one word of the scene's things among them: "blok" is the scene's block,
not a book); a word the lexicon does not know that is two of the scene's words run together is read as both; a word
the lexicon does not know that is the clipped start of exactly one of the scene's words, with a pet ending or not
("choc", "choccy" for "chocolate"), is read as that word.

Only words unknown to the lexicon are touched, so a real word that names something the scene lacks ("the
grapefruit") is never turned into one it holds; and a slip is read only as a word the planner itself knows or a
word of a thing perception lists in this scene (its inventory), never guessed from a wider dictionary."""

from __future__ import annotations

import re
import unicodedata
from functools import lru_cache

from lemminflect import getAllLemmas

from ...perception.colors import BASE_COLOURS
from ...perception.variants import KIND_OF
from .lexicon import DETERMINERS, FILLERS, VERBS
from .mentions import ABSTRACT, _closed_words
from .specs import KEYS as SPEC_KEYS
from .things import NOT_THINGS

_MIN = 3  # shorter words are too close to too many others
# Contractions typed without the apostrophe that spell no other word ("its", "were", "lets", "id" do).
_UNMARKED = {
    w.replace("'", ""): w
    for w in ["don't", "doesn't", "didn't", "isn't", "aren't", "wasn't", "can't", "won't", "shouldn't", "wouldn't"]
    + ["couldn't", "that's", "there's", "what's", "here's", "you're", "they're", "i've", "i'm", "we've", "you've"]
}


# Chat spellings and shorthand of colours that no keystroke slip reaches ("da bowl", "grn on blu").
_CHAT = {"da": "the", "tha": "the", "grn": "green", "blu": "blue", "ylw": "yellow", "yllw": "yellow", "wht": "white"}
_CHAT |= {"blk": "black", "brn": "brown", "gry": "grey", "prpl": "purple", "orng": "orange", "rd": "red"}
_CHAT |= {"thn": "then", "nxt": "next", "frst": "first"}
_CHAT |= {"rn": "right now", "gotta": "got to", "evry": "every"}
# arrows typed as one character: the ASCII arrow the rules read ("stove ➜ plate"); one pointing back says the
# same carry the other way round ("plate ← the black bowl": the black bowl goes to the plate)
_ARROWS = re.compile(r"\s*(?:➜|➔|→|⇒|⟶|=>|➡)\s*")
_BACK_ARROW = re.compile(r"^([^.;!?←]+?)\s*(?:←|⟵|<-+|⇐)\s*([^.;!?←]+?)(\s*[.;!?]*)$")
# "pleas" is a word (pleas of a plea), but a request's last word or its first is the courtesy with a slip
_PLEAS = re.compile(r"(?:^|(?<=[,;]\s))pleas\b(?=\s+[a-z])|\bpleas(?=\s*[.!?]*\s*$)|(?<=,\s)pleas(?=\s*[,.!?])", re.I)


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
    keys = {w for k in SPEC_KEYS for w in k.split()}  # "dst", "obj": a spec's keys (rules/specs.py)
    words = (
        _closed_words() | set(DETERMINERS) | set(KIND_OF) | set(BASE_COLOURS) | ABSTRACT | NOT_THINGS | fillers | keys
    )
    return frozenset(w for w in words if w.isalpha())


def _scene_words(inventory: tuple[str, ...]) -> frozenset[str]:
    words = {w for n in inventory for w in re.sub(r"\s*\(\d+\)$", "", n).lower().replace("_", " ").split()}
    return frozenset(w for w in words if w.isalpha())


@lru_cache(maxsize=1)
def _action_words() -> frozenset[str]:
    """The one-word forms of the planner's action verbs ("stack", "put", "grab")."""
    return frozenset(f for forms in VERBS.values() for f in forms if f.isalpha())


def _fix(word: str, known: frozenset[str], scene: frozenset[str], verb_slot: bool = False) -> str | None:
    if len(word) < _MIN or word in known or getAllLemmas(word):
        return None
    # a letter held for emphasis ("pleeease", "baskettt"): the word with the run said once, or twice ("sooo")
    for held in (re.sub(r"(.)\1{2,}", r"\1", word), re.sub(r"(.)\1{2,}", r"\1\1", word)):
        if held != word and (held in known or getAllLemmas(held)):
            return held
    near = {k for k in known if len(k) >= _MIN and _one_slip(word, k)}
    if len(near) == 1:
        return next(iter(near))
    # several words one keystroke away ("blok": block, book): the one the scene's things are called by, if one is
    in_scene = near & scene
    if len(in_scene) == 1:
        return next(iter(in_scene))
    # where a part's verb goes ("stak the cube ...": stack, stay): the one action verb the planner knows, if one is
    actions = near & _action_words()
    if verb_slot and len(actions) == 1:
        return next(iter(actions))
    splits = [
        f"{word[:i]} {word[i:]}" for i in range(_MIN, len(word) - _MIN + 1) if word[:i] in scene and word[i:] in scene
    ]
    if len(splits) == 1:
        return splits[0]
    return _unclipped(word, scene)


_PET_ENDINGS = ("ies", "ie", "y", "s", "o")
_MIN_CLIP = 4  # "choc": shorter starts are shared by too many words


def _unclipped(word: str, scene: frozenset[str]) -> str | None:
    """The one scene word `word` is a clipped form of: its start, of at least four letters and at most all but two
    of the word's, said as is or with a pet ending ("choccy": "choc" + "cy", a doubled consonant and "y")."""
    stems = {word}
    for end in _PET_ENDINGS:
        stem = word.removesuffix(end)
        if stem != word:
            stems |= {stem, stem[:-1] if len(stem) > 1 and stem[-1] == stem[-2] else stem}
    found = {w for w in scene for s in stems if len(s) >= _MIN_CLIP and len(w) >= len(s) + 2 and w.startswith(s)}
    return next(iter(found)) if len(found) == 1 else None


def plain_letters(text: str) -> str:
    """Accented letters as their plain letters ("soufflé" -> "souffle", "crème" -> "creme"): the planner's words and
    the scene's names are written without accents, and a word cut at an accent names nothing."""
    return "".join(c for c in unicodedata.normalize("NFKD", text) if not unicodedata.combining(c))


_PART_START = re.compile(r"(?:^|[,;:.!?]|\s-|\band|\bthen)\s*$", re.IGNORECASE)


def corrected(instruction: str, inventory: tuple[str, ...] = ()) -> str:
    """`instruction` with each slip read as the word it misses (accents dropped first); unchanged when it has
    none."""
    instruction = plain_letters(instruction)
    # chat shorthand between two words: "pick it up n put it ...", "cube & bowl", "w/ the sponge"
    instruction = re.sub(r"(?<=\w) (?:n|&|'n'?) (?=\w)", " and ", instruction)
    instruction = re.sub(r"(?<![\w/])w/ ?(?=\w)", "with ", instruction, flags=re.IGNORECASE)
    # a contraction typed without its apostrophe ("once thats done", "dont"): one no other word is spelled as
    instruction = re.sub(
        rf"\b({'|'.join(_UNMARKED)})\b",
        lambda m: _UNMARKED[m.group(1).lower()],
        instruction,
        flags=re.IGNORECASE,
    )
    instruction = re.sub(
        rf"\b({'|'.join(_CHAT)})\b", lambda m: _CHAT[m.group(1).lower()], instruction, flags=re.IGNORECASE
    )
    instruction = _PLEAS.sub("please", instruction)
    instruction = _ARROWS.sub(" -> ", instruction)
    instruction = " ".join(
        _BACK_ARROW.sub(r"\2 -> \1\3", part) for part in re.split(r"(?<=[.;!?])\s+", instruction.strip())
    )
    scene = _scene_words(inventory)
    known = _planner_words() | scene

    def fix(m: re.Match) -> str:
        word = m.group(0)
        # first in its part, before a word that is no verb itself ("stak the cube", not "plase put the cube")
        after = instruction[m.end() :].split()
        verb_slot = bool(_PART_START.search(instruction[: m.start()])) and not (
            after and after[0].lower().strip(",.;:") in _action_words()
        )
        better = _fix(word.lower(), known, scene, verb_slot)
        return better if better is not None else word

    return re.sub(r"(?<!['\w])[A-Za-z]+(?!['\w])", fix, instruction)
