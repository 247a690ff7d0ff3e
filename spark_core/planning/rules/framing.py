"""Words that only frame a request, before its verb: "i'd appreciate it if you put ...", "do you think you could put
...", "how about putting ...", "why don't you place ...". They name no thing and ask nothing of their own; the request
is what follows, from the verb on ("putting" said as "put").

The frame is read past only when no word of it names a thing and it holds no negation but the suggestion "why don't
you" / "why not" ("i don't want you to put ..." asks the opposite), so nothing said is dropped."""

from __future__ import annotations

import re
from collections.abc import Callable
from functools import cache

from lemminflect import getAllLemmas, getLemma

from ...perception.variants import KIND_OF
from .lexicon import VERBS

_NEGATION = frozenset(["not", "no", "never", "don't", "dont", "doesn't", "won't", "can't", "cannot", "n't", "nor"])
_SUGGESTION = (["why", "don't", "you"], ["why", "dont", "you"], ["why", "do", "not", "you"], ["why", "not"])
# Words that make the sentence a question or a report about the request, not the request ("what happens if you put
# ...", "did you put ...", "tell me why you put ..."): no frame holds one, but for the suggestions "how about", "what
# about", "why don't you".
_ASKS_ABOUT = frozenset(
    ["what", "why", "how", "when", "where", "who", "whom", "whose", "which", "whether", "did", "does", "had"]
    + ["happen", "happens", "happened", "tell", "explain", "know", "remember", "wonder", "wondering", "guess"]
)
_ABOUT = (["how", "about"], ["what", "about"])


@cache
def verb_words() -> frozenset[str]:
    """The first word of every verb form the lexicon knows ("pick" of "pick up")."""
    return frozenset(f.split()[0] for forms in VERBS.values() for f in forms)


def _base(word: str) -> str | None:
    """The word as one of the planner's verbs ("putting" -> "put"), or None."""
    verbs = verb_words()
    if word in verbs:
        return word
    if word.endswith("ing"):
        lemma = getLemma(word, upos="VERB")
        if lemma and lemma[0] in verbs:
            return lemma[0]
    return None


_DETERMINERS = frozenset(["the", "a", "an", "this", "that", "these", "those", "my", "your", "some", "its"])


def _no_thing(word: str, before: str, names_nothing: Callable[[str], bool]) -> bool:
    """The frame's word names no thing: a word that names none, or one the lexicon also knows as something besides a
    noun ("mind", "think", "how") and no kind of thing, unless a determiner comes before it ("the box")."""
    if names_nothing(word):
        return True
    if before in _DETERMINERS or word in KIND_OF:
        return False
    return bool(set(getAllLemmas(word)) - {"NOUN"})


def unframed(instruction: str, names_nothing: Callable[[str], bool]) -> str | None:
    """The request after the words that frame it, from its first verb on; None when nothing frames it, or the
    frame names a thing (`names_nothing` says a word names none) or negates."""
    text = instruction.lower().replace("\u2019", "'").replace("'d ", " would ")
    words = re.findall(r"[a-z']+|[,;:!?.]", text)
    for n, word in enumerate(words):
        verb = _base(word)
        if verb is None:
            continue
        frame = [w for w in words[:n] if w not in ",;:!?."]
        if not frame:
            return None
        suggestion = any(frame[: len(s)] == s for s in _SUGGESTION)
        opening = next((len(s) for s in (*_SUGGESTION, *_ABOUT) if frame[: len(s)] == s), 0)
        if set(frame[opening:]) & _ASKS_ABOUT or (not opening and frame[0] in _ASKS_ABOUT):
            return None
        if (set(frame) & _NEGATION or any(w.endswith("n't") for w in frame)) and not suggestion:
            return None
        rest = frame[opening:]
        if not all(_no_thing(w, rest[i - 1] if i else "", names_nothing) for i, w in enumerate(rest)):
            return None
        return " ".join([verb, *words[n + 1 :]])
    return None
