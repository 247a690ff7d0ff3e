"""A verb the planner does not know, said in a frame that only a move fits: "<verb> the cube into the bowl", "<verb>
the block onto the plate". English puts a thing somewhere with almost any verb of handling in this frame (a caused
motion: "dunk", "wedge", "bung", "ease"), so the frame, not the verb, says what is done: the thing goes where the
preposition says.

The frame is narrow: the verb opens the request (after a courtesy such as "please" or "can you"), the lexicon knows
it as a verb, and the place is said with a preposition that can only mean where the thing goes ("into", "onto", "on
top of", "inside", "atop"), never "in" or "on", which may only say where it already is ("eat the pear in the
pot"). Verbs that change, use up or only look at a thing are no move, whatever the frame.

A verb said again with "re-" that the lexicon does not know ("restack") is the verb itself."""

from __future__ import annotations

from lemminflect import getAllLemmas

from .lexicon import VERBS

# Words that may come before the request's own verb.
_COURTESY = frozenset(["please", "pls", "plz", "kindly", "can", "could", "would", "will", "you", "u", "just", "now"])
# Prepositions that say where a thing goes, and nothing else.
GOES_TO = ("into", "onto", "on top of", "inside", "atop", "on to")
# Verbs that change, use up or only perceive or talk about a thing: what they do to it is no move.
_NO_MOVE = frozenset(
    ["eat", "drink", "cook", "bake", "fry", "boil", "roast", "grill", "melt", "burn", "heat", "cool", "freeze"]
    + ["cut", "slice", "chop", "dice", "peel", "grate", "mash", "mix", "stir", "blend", "whisk", "squeeze"]
    + ["paint", "colour", "color", "draw", "write", "read", "sing", "say", "tell", "ask", "explain", "describe"]
    + ["look", "see", "watch", "show", "count", "name", "imagine", "think", "wonder", "love", "like", "hate"]
    + ["want", "need", "smell", "taste", "hear", "feel", "photograph", "film", "scan", "check", "inspect"]
    + ["break", "smash", "crush", "destroy", "tear", "rip", "fold", "bend", "twist", "turn", "spin", "shake"]
    + ["translate", "convert", "transform", "change", "make", "build", "keep", "let", "leave", "forget", "remember"]
)


def leading_verb(tokens: list[str]) -> int | None:
    """The index of the word that opens the request when the lexicon knows it as a verb that may move a thing
    (after any courtesy words); None otherwise."""
    n = 0
    while n < len(tokens) and tokens[n] in _COURTESY:
        n += 1
    if n >= len(tokens):
        return None
    word = tokens[n]
    lemmas = getAllLemmas(word).get("VERB", ())
    if not lemmas or word in _NO_MOVE or any(lemma in _NO_MOVE for lemma in lemmas):
        return None
    return n


def goes_to(tokens: list[str], start: int) -> bool:
    """The mention at `start` is introduced by a preposition that only says where a thing goes."""
    return any(tokens[start : start + len(p.split())] == p.split() for p in GOES_TO)


def said_again(word: str) -> str | None:
    """The action of one of the planner's verbs said again with "re-" that the lexicon does not know ("restack",
    "re-stack"); None for any other word (a known word such as "remove" keeps its own sense)."""
    verb = word.removeprefix("re").removeprefix("-")
    if verb == word or getAllLemmas(word) or not verb.isalpha():
        return None
    return next((action for action, forms in VERBS.items() if verb in forms), None)
