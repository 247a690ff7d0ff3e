"""Which of the learned segmenter's categories a prompt's words can name, by the same word rules the `sim` oracle
applies to scene objects (perception/naming.py): a category whose name the words contradict is no match at any
sentence similarity, and a lone noun names every category it may mean, so that two such objects in view are
several (an ambiguous label) instead of whichever the sentence encoder ranks first."""

from __future__ import annotations

from ..naming import mismatch, package_members, word_forms, word_kind
from ..variants import GENERIC, MATERIALS
from .categories import CATEGORIES


def contradicted(core: str, category: int) -> bool:
    """The prompt's words (colours taken out) cannot name the category: another kind, another product ("bbq
    sauce" is no tomato sauce), a part of something it is not part of. Checked against the category's name and
    the kinds its description names ("drawer handle": on the cabinet drawer), not the description's other words:
    they say what the category usually looks like ("square wooden peg": a round peg is a peg all the same) or
    comes in ("carton of milk": "carton" is no word of the milk's own name)."""
    c = CATEGORIES[category]
    return mismatch(core, c.name, _kind_words(c.description)) is not None


def _kind_words(description: str) -> str:
    """The description's words that name a kind of thing ("the cabinet's sliding drawer": cabinet, drawer); a
    material is no kind here ("dark glass wine bottle": no drinking glass)."""
    words = description.replace(",", " ").replace("'s", "").lower().split()
    return " ".join(w for w in words if word_kind(w) is not None and w not in MATERIALS)


def lone_noun_categories(core: str) -> set[int]:
    """The categories a prompt that is one noun names ("sauce", "bottle", "carton"): every category whose name
    ends in it; for a package noun that is no kind of thing ("box", "carton", "tin"), every category said to come
    in it too (or, when none is, in a package of its kind: `naming.package_members`); for a word naming no kind
    ("object", "item"), every category. Empty for a prompt of several words or a noun naming none."""
    words = core.split()
    if len(words) != 1:
        return set()
    forms = word_forms(words[0])
    things = [i for i, c in enumerate(CATEGORIES) if c.thing]
    if forms & GENERIC:  # "the object", "the item": anything
        return set(things)
    # its own noun, or a word of its kind ("dish": the bowl, the plate and the ramekin alike; "bin": basket, tray)
    kinds = set().union(*(word_kind(f) or () for f in forms))
    out = {i for i in things if CATEGORIES[i].name.split()[-1] in forms | kinds}
    descriptions = [CATEGORIES[i].description for i in things]
    # a package noun that is a kind too ("bottle"): the bottled products as well as the wine bottle
    packaged = package_members(words[0], descriptions) or package_members(words[0], descriptions, kind_too=True)
    return out | {things[k] for k in packaged or ()}
