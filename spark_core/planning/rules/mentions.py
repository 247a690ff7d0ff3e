"""Every thing an instruction names must be in the scene: the objects and destinations of its clauses, the
things those are located by ("the bowl next to the toaster": the toaster), and the noun phrases the parser read
past (a trailing clause, an unknown preposition: "grab the tomato sauce for the basket"). A plan is made only
when perception finds each of them; one it finds nothing for refuses the whole instruction, so an absent object
is never planned around, in any step or role."""

from __future__ import annotations

import re

from ...perception.colors import BASE_COLOURS
from ...perception.colors import SYNONYMS as COLOUR_SYNONYMS
from ...perception.qualifiers import QUALIFIERS, split_relation
from ...perception.variants import MATERIALS, SHAPES, SIZES
from .lexicon import CONTENTS, DETERMINERS, PRONOUNS, REGIONS, TABLE
from .parse import Clause, is_pronoun
from .phrases import singular
from .rewrite import sentences
from .things import names_a_thing

# Words that locate or qualify without naming a thing in the scene ("the table's centre", "the left side").
PLACE_WORDS = frozenset(
    ["center", "centre", "middle", "left", "right", "front", "back", "side", "edge", "corner", "end", "top", "bottom"]
    + ["robot", "you", "me", "us", "arm", "gripper", "hand", "hands", "air", "floor", "ground", "way", "rest", "rim"]
    + ["surface", "place", "position", "spot", "half", "area", "row", "line", "direction", "distance", "moment"]
    + ["time", "goal", "task", "job", "plan", "idea", "aim", "one", "ones", "other", "others", "thing", "things"]
    + ["lot", "bit", "second", "minute", "kitchen", "scene", "workspace", "world", "room", "camera", "view"]
    + ["inside", "outside", "interior", "contents", "content", "upright", "same", "rest", "whole", "two", "three"]
    # arrangements the things make, not things ("so they form a tower")
    + ["tower", "stack", "pile", "heap", "group", "pair", "set", "column", "order"]
    + [w for t in TABLE for w in t.split()]
    + list(QUALIFIERS)
)
# Where a noun phrase read past the clauses ends: a preposition, conjunction, relative or verb-like word.
_NP_STOP = frozenset(
    ["on", "onto", "in", "into", "to", "from", "of", "with", "at", "by", "near", "next", "beside", "between", "under"]
    + ["over", "inside", "off", "for", "and", "or", "but", "then", "so", "that", "which", "who", "is", "are", "be"]
    + ["should", "must", "will", "would", "can", "goes", "go", "belongs", "belong", "needs", "sits", "stays", "not"]
    + ["up", "down", "out", "away", "back", "please", "too", "first", "again", "instead", "rather", "than", "as"]
    + ["if", "when", "while", "without", "until", "before", "after", "it", "them", "there", "here", "where"]
)
# Words that describe a thing without naming it: a phrase is about a thing the clauses name when it shares a noun.
ATTRIBUTES = frozenset([*BASE_COLOURS, *COLOUR_SYNONYMS, *MATERIALS, *SHAPES, *SIZES])
_DET = re.compile(r"\b(?:the|a|an|some|my|your|this|these|those) ")


def anchors(phrase: str) -> list[str]:
    """The things `phrase` locates its object by ("black bowl next to plate" -> ["plate"]; "bowl between plate
    and ramekin" -> both), without places that are no object ("table center")."""
    _, relation, found = split_relation(phrase)
    if relation is None:
        return []
    return [
        a for a in found if not set(a.split()) - {"of", "the"} <= PLACE_WORDS and a not in PRONOUNS and names_a_thing(a)
    ]


def clause_mentions(clauses: list[Clause]) -> list[str]:
    """Object phrases of the clauses and the anchors of their relations, in order, each once."""
    out: dict[str, None] = {}
    for c in clauses:
        for p in (c.obj, c.target, c.tool, c.source):
            if not p or is_pronoun(p):
                continue
            if p == c.obj and c.action == "pour" and c.source and c.source != c.obj:
                continue  # what is poured out of the source (its beads, its water) is the source's to hold
            out.setdefault(p, None)
            for a in anchors(p):
                out.setdefault(a, None)
    return list(out)


def _words(phrases: list[str]) -> set[str]:
    return {f for p in phrases for w in re.findall(r"[a-z]+", p.lower()) for f in (w, singular(w))}


def read_past(instruction: str, clauses: list[Clause]) -> list[str]:
    """Noun phrases of the instruction that share no word but attributes with any clause's phrase, and whose last
    word is no place word: what the parser dropped, which must still be in the scene. (A phrase that shares a noun,
    "red block held" for "red block", is the clause's own thing with a verb after it.)"""
    said = _words([*clause_mentions(clauses), *(c.obj for c in clauses if c.obj)])
    out: dict[str, None] = {}
    for sentence in sentences(instruction):
        for m in _DET.finditer(sentence):
            words: list[str] = []
            for w in sentence[m.end() :].replace(",", " , ").split():
                if w in _NP_STOP or w == "," or not re.fullmatch(r"[a-z][a-z'-]*", w) or len(words) == 3:
                    break
                if w not in DETERMINERS:
                    words.append(w.removesuffix("'s"))
            if not words:
                continue
            head = words[-1]
            if {head, singular(head)} & PLACE_WORDS or head in REGIONS or set(words) & set(CONTENTS):
                continue  # a place, or what a container holds ("so the beads fall in")
            if not names_a_thing(" ".join(words)):
                continue  # no thing at all ("the gap", "a sec", "the end"): nothing perception could look for
            if any({w, singular(w)} & said for w in words if w not in ATTRIBUTES):
                continue
            out.setdefault(" ".join(words), None)
    return list(out)
