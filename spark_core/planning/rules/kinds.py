"""A noun the instruction says must name something the scene holds, not a neighbour of it that a sentence encoder
grounds with a middling score. Perception grounds a phrase by similarity, so "the grapefruit juice" finds the
orange juice and "the sour cream" the cream cheese; these checks compare what was said with the names of what
perception can list of the scene (its inventory), word by word:

- another variety: the phrase's head is the head of things the scene holds ("juice"), but a noun before it names a
  variety none of them is ("grapefruit" where the scene's juice is the orange juice), or a flavour or base that
  makes it another product even where the scene names the thing by its head alone ("chocolate milk");
- a modifier taken for a thing: the phrase's head is no thing's head or kind in the scene, only a word that
  describes one ("cream" of the cream cheese, "salad" of the salad dressing), unless that thing is named by its
  packaging ("the wine" of the wine bottle);
- other contents: a thing poured out of a container may be out of sight inside it, but when the scene shows what
  its containers hold ("beads"), contents of another kind ("water", "rice") are not there; and when it shows
  none, only things a container may hold out of sight (beads, marbles, balls: the rigid things a scene can hold)
  or words that name no kind ("the contents") may be poured: a substance ("water", "coffee") the scene cannot
  show is not taken on the sentence's word.

With no inventory (perception that cannot list the scene), nothing is checked here."""

from __future__ import annotations

import re

from lemminflect import getAllLemmas

from ...perception.colors import BASE_COLOURS
from ...perception.qualifiers import QUALIFIERS, split_relation
from ...perception.variants import GENERIC, KIND_OF, PACKAGING, PARTS, SPELLINGS
from .lexicon import DETERMINERS
from .mentions import ABSTRACT, ATTRIBUTES, PLACE_WORDS, _closed_words
from .phrases import singular

# What a container holds, named without saying what it is: no claim about its kind.
_ANY_CONTENTS = frozenset(
    ["contents", "content", "stuff", "everything", "things", "it", "them", "all", "bits", "liquid"]
)
# Things a scene may show inside a container: what is poured.
_SHOWN_CONTENTS = frozenset(["bead", "beads", "marble", "marbles", "ball", "balls", "pellet", "pellets"])


# Flavours and bases that make a food or drink another product ("chocolate milk", "almond milk", "tomato soup"):
# said of a thing the scene names by its head alone, the scene's thing is not it.
_FLAVOURS = frozenset(
    ["chocolate", "strawberry", "vanilla", "banana", "almond", "soy", "oat", "coconut", "caramel", "mint", "cherry"]
    + ["mango", "peach", "raspberry", "blueberry", "hazelnut", "honey", "maple", "garlic", "onion", "mushroom"]
    + ["chicken", "beef", "pumpkin", "lentil", "pea", "goat", "skim", "skimmed", "buttermilk", "cinnamon"]
)


def _forms(word: str) -> set[str]:
    out = {word, singular(word), word[:-1] if word.endswith("s") and len(word) > 3 else word}
    return out | {SPELLINGS[f] for f in out if f in SPELLINGS}


def _kind(word: str) -> set[str]:
    return set().union(*(KIND_OF.get(f, frozenset()) for f in _forms(word)))


def _names(inventory: tuple[str, ...]) -> list[list[str]]:
    return [re.sub(r"\s*\(\d+\)$", "", n).lower().replace("_", " ").split() for n in inventory]


def _words(phrase: str) -> list[str]:
    """The phrase's own words, before any relation to another thing, without qualifiers and place words."""
    head = re.split(r"\s+not\s+", split_relation(phrase)[0])[0]
    skip = frozenset(QUALIFIERS) | PLACE_WORDS | set(DETERMINERS)
    return [w for w in re.findall(r"[a-z]+", head.lower()) if w not in skip]


def _is_head(word: str, name: list[str]) -> bool:
    """`word` names the thing `name` is: its head noun, or a word of the head's kind."""
    return bool(_forms(word) & _forms(name[-1]) or _kind(word) & _forms(name[-1]))


def _noun(word: str) -> bool:
    pos = getAllLemmas(word)
    return not pos or "NOUN" in pos


def _known_noun(word: str) -> bool:
    """A noun the lexicon knows ("grapefruit"), not a shorthand it lacks ("atop"): a name it lacks is
    mentions.foreign_modifiers' to check."""
    return "NOUN" in getAllLemmas(word) and word not in ABSTRACT


def other_variety(phrase: str, inventory: tuple[str, ...]) -> str | None:
    """The noun of `phrase` that names a variety no thing of its kind in the scene is ("grapefruit"), or None."""
    words = _words(phrase)
    if len(words) < 2 or words[-1] in PACKAGING or words[-1] in PARTS:
        return None
    names = _names(inventory)
    same = [n for n in names if _is_head(words[-1], n)]
    held = {f for n in names for w in n for f in _forms(w)}
    own = {f for n in same for w in n for f in _forms(w)}  # of the things of its kind ("chocolate pudding" is not)
    flavour = next((w for w in words[:-1] if w in _FLAVOURS and not _forms(w) & own), None)
    if same and flavour:
        return flavour  # "the chocolate milk" where the scene's milk is named by its head alone: another product
    if not same or not all(len(n) > 1 for n in same):
        return None  # no such thing, or one named by its head alone ("plate": "the dinner plate" is it)
    skip = ATTRIBUTES | _closed_words()
    head_kind = KIND_OF.get(words[-1], frozenset())
    for w in words[:-1]:
        if w in skip or len(w) < 3 or not _known_noun(w) or _forms(w) & held:
            continue
        if KIND_OF.get(w, frozenset()) & head_kind:
            continue  # a word of the head's own kind says it again ("the green target patch": a patch, the area)
        return w
    return None


def modifier_for_thing(phrase: str, inventory: tuple[str, ...]) -> str | None:
    """The head of `phrase` when the scene holds nothing it names, only a thing it describes ("cream"), or None."""
    words = _words(phrase)
    if not words:
        return None
    head = words[-1]
    if head in GENERIC or head in PACKAGING or head in PARTS or head in BASE_COLOURS or not _noun(head):
        return None
    names = _names(inventory)
    if any(_is_head(head, n) for n in names):
        return None
    described = [n for n in names if any(_forms(head) & _forms(w) for w in n[:-1])]
    if described and not any(n[-1] in PACKAGING for n in described):
        return head
    return None


def other_contents(poured: str, inventory: tuple[str, ...]) -> str | None:
    """What is poured, when the scene shows what its containers hold and that is something else, or shows nothing
    inside and it is no rigid thing a container may hide ("water"); None otherwise."""
    words = _words(poured)
    if not words or words[-1] in _ANY_CONTENTS:
        return None
    names = _names(inventory)
    shown = [n for n in names if _forms(n[-1]) & _SHOWN_CONTENTS]
    if not shown:
        # nothing shown inside: rigid things may be out of sight in it; a substance the scene cannot show is not
        rigid = _forms(words[-1]) & _SHOWN_CONTENTS or any(_is_head(words[-1], n) for n in names)  # or the mug
        return None if not names or rigid else words[-1]
    if any(_is_head(words[-1], n) or _forms(words[-1]) & _forms(n[-1]) for n in shown):
        return None
    return words[-1]
