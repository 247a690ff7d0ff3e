"""Is a word a thing? Only a word that names a thing can make an instruction refuse when perception does not find
it: a concrete noun ("saucer", "tomato") is an object the robot would have to see; a word the parser could not
place that is no noun at all (an adverb, a verb, an adjective: "ideally", "squash", "going") or a place or manner
noun ("spot", "side", "gap", "way") names nothing perception could look for.

Parts of speech come from lemminflect's English lexicon (the SPECIALIST lexicon, shipped in its wheel: offline);
a word the lexicon does not know (a brand, "akita") counts as a thing, so an unknown name still refuses."""

from __future__ import annotations

from functools import lru_cache

from lemminflect import getAllLemmas

# Nouns that name where or how, not what: a place word said of a thing ("the spot by the plate", "the gap
# between ..."), an amount or a moment ("a bit", "a sec"), the robot itself ("your arm").
NOT_THINGS = frozenset(
    ["spot", "area", "side", "corner", "edge", "end", "middle", "center", "centre", "gap", "space", "place"]
    + ["position", "location", "surface", "top", "bottom", "front", "back", "left", "right", "half", "part"]
    + ["way", "direction", "distance", "state", "goal", "result", "outcome", "moment", "sec", "second", "minute"]
    + ["time", "bit", "while", "order", "rest", "arm", "gripper", "hand", "robot", "yourself", "care", "mess"]
    + ["round", "around", "idea", "job", "task", "plan", "aim", "thing", "things", "one", "ones", "row", "line"]
    # a chance, a favour, a point of view: said about the request, never a thing in it
    + ["chance", "opportunity", "favour", "favor", "point", "view", "perspective", "viewpoint"]
    # pronouns name who speaks or listens, not an object ("the end state i am after")
    + ["i", "me", "you", "we", "us", "they", "them", "he", "she", "him", "her", "it"]
    # ... and as they are texted ("can u", "ur arm")
    + ["u", "ur", "ya"]
)


# Things the lexicon knows only as another part of speech ("pan" only as a verb): without this, "put the bowl on
# the pan" would read "pan" as a word that names nothing, not as a thing the scene lacks.
NOUNS_IT_MISSES = frozenset(["pan", "pans"])


@lru_cache(maxsize=4096)
def is_thing(word: str) -> bool:
    """True unless `word` is a place/manner noun or, by the lexicon, no noun at all."""
    w = word.lower().strip()
    if not w.isalpha() or w in NOT_THINGS:
        return False
    if w in NOUNS_IT_MISSES:
        return True
    pos = getAllLemmas(w)
    if not pos:
        return True  # unknown to the lexicon: a name, refuse rather than ignore it
    if "NOUN" not in pos:
        return False
    return pos["NOUN"][0] not in NOT_THINGS  # "spots", "corners"


def names_a_thing(phrase: str) -> bool:
    """A phrase names a thing when its head (last word) does."""
    words = phrase.split()
    return bool(words) and is_thing(words[-1])


def adverb_only(word: str) -> bool:
    """A word the lexicon knows only as an adverb ("ideally", "hopefully"): it says how or when, never what."""
    pos = getAllLemmas(word.lower())
    return bool(pos) and set(pos) == {"ADV"}


def is_verb(word: str) -> bool:
    """A word the lexicon knows as a verb ("balance", "twist"): a verb the planner's own list may lack."""
    return "VERB" in getAllLemmas(word.lower())
