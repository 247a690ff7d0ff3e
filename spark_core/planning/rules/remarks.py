"""Remarks: whole sentences after the request that say nothing to do ("lift the red cube. just want to see the grasp
work", "put the block on the plate. don't just set it down next to it", "take the bowl on the stove. the other bowl
can stay where it is"). When every reading of the whole instruction refuses, the planner reads it again without
them (planner._without_remarks): the request must then plan on its own, and a remark may name no kind of thing the
scene lacks, so an absent thing is still refused."""

from __future__ import annotations

import re

from lemminflect import getAllLemmas

from ...perception.variants import KIND_OF
from .lexicon import DETERMINERS
from .phrases import singular
from .rewrite import starts_with_verb
from .things import names_a_thing

# Words that name no thing of the scene, whatever the lexicon says.
_SELVES = frozenset(
    ["myself", "yourself", "itself", "ourselves", "themselves", "himself", "herself", "other", "others"]
)
_SELVES |= {"nothing", "something", "anything", "everything", "stuff"}

# What makes a sentence after the request a remark: a negation (how not to do it), the speaker's own say ("just want
# to see ...", "i do the rest myself"), or a thing left as it is ("the other bowl can stay where it is", "fyi").
_REMARK = re.compile(
    r"\b(?:not|never|don't|dont|doesn't|won't)\b|n't\b|^(?:i|we|my|our|just|fyi|btw|nothing else)\b|"
    r"\b(?:can|should|may|will) (?:stay|remain|be left)\b|\b(?:stays?|remains?) (?:where|as|put)\b|\bfyi\b|\bbtw\b"
)
# A remark never says the request itself in other words ("i want the red cube on the green one").
_WISH = re.compile(r"\b(?:want|need|would like|'d like|wish|prefer) (?:the|it|them|a|an|this|that|those|these)\b")


def remarks(instruction: str) -> tuple[str, list[str]]:
    """The instruction without the remark sentences after its first imperative one, and those remarks; the
    instruction itself and no remarks when it has none (or no sentence is a request said with a verb)."""
    said = [s.strip() for s in re.split(r"(?<=[.!?;])\s+", instruction.strip()) if s.strip()]
    main = next((i for i, s in enumerate(said) if starts_with_verb(_plain(s))), None)
    if main is None or len(said) < 2:
        return instruction, []
    aside = [i for i, s in enumerate(said) if i > main and _REMARK.search(_plain(s)) and not _WISH.search(_plain(s))]
    if not aside:
        return instruction, []
    return " ".join(s for i, s in enumerate(said) if i not in aside), [said[i] for i in aside]


def names_absent(sentence: str, found: list[str]) -> str | None:
    """A word of `sentence` that names a kind of thing none of `found` (perception's phrases and inventory) is of,
    or a noun-only word none of them holds ("don't touch the banana" in a scene without one); None when it names
    no such thing."""
    known = {w for p in found for w in re.findall(r"[a-z]+", p.lower())}
    kinds = set().union(*(KIND_OF.get(w, frozenset()) | KIND_OF.get(singular(w), frozenset()) for w in known))
    for w in re.findall(r"[a-z]+", _plain(sentence)):
        forms = {w, singular(w)}
        if forms & known:
            continue
        kind = next((KIND_OF[f] for f in forms if f in KIND_OF), None)
        if kind is not None:
            if not kind & (known | kinds):
                return w
            continue
        # a word only ever a noun, that names a thing ("laptop"), not a pronoun ("myself") or a word of time or
        # manner ("bit", "way")
        if w not in _SELVES and w not in DETERMINERS and set(getAllLemmas(w)) == {"NOUN"} and names_a_thing(w):
            return w
    return None


def _plain(sentence: str) -> str:
    """Lower case, and a courtesy before the verb gone ("please turn on the stove": a request said with a verb)."""
    text = sentence.lower().replace("\u2019", "'").strip()
    return re.sub(r"^(?:(?:please|kindly|ok|okay|now|so|and|then|robot),?\s+)+", "", text)
