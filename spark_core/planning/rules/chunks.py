"""The noun phrases of a sentence by its words alone, with no parse: what observe looks for when no reading of the
sentence gives it anything to look for ("my plate is missing its bowl", "what about the bowl on the plate").

Perception finding these things does not make a plan: only the learned reader (planning/learned_reader) ranks goals
over them, and a thing perception does not find is refused like any other."""

from __future__ import annotations

import re

from lemminflect import getAllLemmas

from .lexicon import DETERMINERS, PRONOUNS
from .mentions import ATTRIBUTES, PLACE_WORDS
from .phrases import singular
from .rewrite import sentences
from .things import adverb_only, is_thing

# Words after which a word that may also be a verb ("bowl", "plate", "block") is a noun.
_NOUN_BEFORE = frozenset(
    ["the", "a", "an", "my", "your", "his", "her", "its", "their", "our", "this", "that", "these", "those", "some"]
    + ["any", "each", "every", "another", "other", "both", "all"]
)
# Where a list item starts: a word that may also be a verb is a noun right after ("the bowl: plate"). Not the
# sentence's start, where it is the request's verb ("make the red block fly").
_BREAKS = frozenset([",", ":", ";", "-"])
# Words of grammar the lexicon also lists as nouns ("and", "what", "my"): never part of a thing's name.
_FUNCTION = frozenset(
    [*_NOUN_BEFORE, "and", "or", "but", "nor", "so", "then", "than", "what", "which", "who", "whom", "whose", "where"]
    + ["when", "why", "how", "into", "onto", "in", "on", "at", "of", "to", "from", "with", "by", "for", "over", "off"]
    + ["up", "down", "out", "about", "under", "near", "next", "beside", "behind", "between", "inside", "please"]
    + ["not", "no", "none", "is", "are", "be", "was", "it", "its", "i", "me", "you", "we", "us", "they", "them"]
)


_NOT_NAMES = _FUNCTION | PLACE_WORDS | ATTRIBUTES | set(DETERMINERS) | set(PRONOUNS)


def _nounish(word: str, before: str) -> bool:
    """`word` names a thing here: a noun that is no place word, said after a determiner, a describing word or
    another noun when the lexicon also knows it as something else ("the bowl", "wine bottle", not "bowl over")."""
    if len(word) < 3 or word in _NOT_NAMES:
        return False
    if not is_thing(word) or adverb_only(word):
        return False
    other_uses = bool(set(getAllLemmas(word)) - {"NOUN"})
    return not other_uses or before in _NOUN_BEFORE or before in _BREAKS or before in ATTRIBUTES or _noun_only(before)


def _noun_only(word: str) -> bool:
    lemmas = getAllLemmas(word)
    return bool(lemmas) and set(lemmas) == {"NOUN"} and word not in _FUNCTION | PLACE_WORDS and is_thing(word)


def noun_chunks(instruction: str) -> list[str]:
    """Each noun that names a thing, with the describing words and nouns right before it and in its singular
    ("the black bowls" -> "black bowl", "the wine bottle" -> "wine bottle"), in the order said, once each."""
    out: dict[str, None] = {}
    for sentence in sentences(instruction):
        words = [w.removesuffix("'s") for w in re.findall(r"[a-z]+(?:'s)?|[,:;-]", sentence.lower())]
        for i, word in enumerate(words):
            before = words[i - 1] if i else ""
            if not _nounish(word, before):
                continue
            after = i + 1
            while after < len(words) and words[after] in ATTRIBUTES:
                after += 1
            if after < len(words) and _nounish(words[after], words[after - 1]):
                continue  # not the last noun of a name ("wine" of "wine bottle", "akita" of "akita black bowl")
            start = i
            while start > 0 and (words[start - 1] in ATTRIBUTES or _nounish(words[start - 1], "")):
                start -= 1
            out.setdefault(" ".join([*words[start:i], singular(word)]), None)
    return list(out)
