"""Whether a phrase can name a thing, from words alone: the kinds of things (variants.KINDS), colours, shapes,
parts and packaging a prompt claims, checked against a thing's name and description. Both segmenters use it: the
`sim` oracle against each scene object's label, the camera-only `learned` one against its categories."""

from __future__ import annotations

import functools
import re

from lemminflect import getAllLemmas

from .colors import BASE_COLOURS
from .colors import SYNONYMS as COLOUR_SYNONYMS
from .qualifiers import QUALIFIERS
from .text_encoder import SHARED_ENCODER
from .variants import (
    CONSUMABLES,
    GENERIC,
    KIND_OF,
    KINDS,
    MATERIALS,
    NOT_NOUNS,
    PACKAGING,
    PARTS,
    SHAPES,
    SIZES,
    SPELLINGS,
)

_ATTRIBUTES = SHAPES | MATERIALS | SIZES | set(QUALIFIERS) | set(BASE_COLOURS) | set(COLOUR_SYNONYMS)
_FILLER = frozenset(["the", "a", "an", "one", "of", "with", "and", "on", "in", "at", "to"])
# A head noun in no kinds table and not in the object's own words names the object only when the sentence encoder
# puts it this close to the object's own noun ("cooker" / stove 0.66; "mustard" / ketchup 0.51, "ball" / block 0.28).
UNKNOWN_NOUN_MIN_COSINE = 0.55
# A food named with a noun before its own (`_other_food`) is the object when the encoder puts the phrase this near the
# object's name: the noun only says what it is made of or where it comes from.
SAME_PRODUCT_MIN_COSINE = 0.85


def _words(text: str) -> list[str]:
    return [SPELLINGS.get(w, w) for w in re.findall(r"[a-z]+", text.lower()) if w not in _FILLER]


def word_forms(word: str) -> set[str]:
    """The word and its singular candidates ("cookies" -> cookie, "boxes" -> box)."""
    out = {word}
    if word.endswith("s") and not word.endswith("ss"):
        out |= {word[:-1], word[:-2] if word.endswith("es") else word[:-1]}
    return out


def _kinds_of(word: str) -> int:
    """How many kinds `word` names ("dish": plate, bowl, ramekin)."""
    return sum(bool(word_forms(word) & k) for k in KINDS)


def word_kind(word: str) -> frozenset[str] | None:
    """Every word of the kind (or kinds) `word` names, or None when the kinds table does not know it."""
    return next((KIND_OF[f] for f in word_forms(word) if f in KIND_OF), None)


def _colours(words: list[str]) -> set[str]:
    """Colour words (synonyms to base names); a material ("wooden") is no colour claim."""
    return {c for w in words if w not in MATERIALS for c in [COLOUR_SYNONYMS.get(w, w)] if c in BASE_COLOURS}


def mismatch(prompt: str, name: str, description: str, part_is_whole: bool = True) -> str | None:
    """Why `prompt` cannot mean the object `name` ("label: description"), or None when nothing contradicts it.
    A prompt names a colour the object does not have, or a shape; a kind of thing (variants.KINDS) the object
    is not (the head noun, or the thing a part belongs to: "oven door handle" is no cabinet drawer handle,
    while "stove knob" may be the stove itself, unless `part_is_whole` is False); or, on the object's own noun,
    a distinguishing word where the object has another ("bbq sauce" vs "tomato sauce", "beer bottle" vs "wine
    bottle"). The head noun decides: a modifier naming the object counts only before a part or package noun ("wine
    glass" is no wine bottle); a head noun in no kinds table goes through `_unknown_head`."""
    text = re.sub(r"^(.+?) of (.+)$", r"\2 \1", prompt.lower())  # "drawer of the cabinet": its noun is drawer
    pw = _words(text)
    if not pw:
        return None
    doc_words = _words(f"{name} {description}")
    doc = {f for w in doc_words for f in word_forms(w)}
    want, have = _colours(pw), _colours(doc_words)
    if want and have and not want & have:
        return f"colour: {', '.join(sorted(want))} vs {', '.join(sorted(have))}"
    shapes, own_shapes = set(pw) & SHAPES, doc & SHAPES
    if shapes and own_shapes and not shapes & own_shapes:
        return f"shape: {', '.join(sorted(shapes))} vs {', '.join(sorted(own_shapes))}"
    nw = _words(name)
    # what the thing is: the words before "with" ("the cabinet with a drawer" is a cabinet)
    said_kinds = _words(re.sub(r"\bwith\b.*$", "", text)) or pw
    kinds = [(w, k) for w in said_kinds if (k := word_kind(w)) is not None]
    if kinds:
        *owners, (_, head_kind) = kinds
        # strictly the object's own noun must be of the head's kind; else its description may say it
        is_head = head_kind & word_forms(nw[-1]) if nw and not part_is_whole else head_kind & doc
        # a modifier naming the object stands for it only through a part or its packaging ("stove knob", "ketchup
        # bottle"), or when it is the object's own noun ("burner plate" of a stove): "wine glass" is no wine bottle
        # (a wide word, of several kinds, says what a thing is for: a "dish towel" is no plate)
        own_noun = any(k & word_forms(nw[-1]) and _kinds_of(w) == 1 for w, k in owners) if nw else False
        via_owner = owners and part_is_whole and (kinds[-1][0] in PARTS | PACKAGING or own_noun)
        foreign = [w for w, k in owners if not k & doc]
        if nw and head_kind & word_forms(nw[-1]) and kinds[-1][0] not in PARTS | PACKAGING:
            # the object is of the head's kind: another object's kind before it says what it is for ("bottle
            # rack"); food or drink says what it holds ("beer bottle" is no wine bottle)
            foreign = [w for w in foreign if word_forms(w) & CONSUMABLES]
        if foreign or not via_owner and not is_head:
            return f"kind: {' '.join(w for w, _ in kinds)}"
    attributes = _ATTRIBUTES
    said_head = said_kinds[-1]
    if said_head not in attributes | GENERIC | NOT_NOUNS and word_kind(said_head) is None and nw:
        why = _unknown_head(said_head, [w for w in said_kinds[:-1] if w not in attributes], nw, doc)
        if why:
            return why
    if said_head in PARTS and nw:
        why = _unknown_owner(said_kinds[:-1], nw, doc)
        if why:
            return why
    same_noun = bool(nw) and bool((word_forms(pw[-1]) | (word_kind(pw[-1]) or frozenset())) & word_forms(nw[-1]))
    if len(pw) > 1 and len(nw) > 1 and same_noun:
        # "whiskey flask" is no wine bottle: the same kind of noun, and a word of its own where the object has another
        said = {w for w in pw[:-1] if w not in attributes and word_kind(w) is None and not word_forms(w) & doc}
        # the object's own distinguishing words, kinds included: "beer bottle" is not the "wine bottle"
        own = {w for w in nw[:-1] if w not in attributes and w not in pw}
        if said and own:
            return f"{pw[-1]}: {' '.join(sorted(said))} vs {' '.join(sorted(own))}"
    product = said_kinds[:-1]
    if word_forms(said_head) & PACKAGING and any(word_forms(w) & CONSUMABLES for w in product):
        # "the mustard bottle", "a tin of tomato sauce": a package said by the food or drink it holds is that
        # product's (the bbq sauce's bottle is no mustard bottle, nor a tomato sauce tin)
        why = mismatch(" ".join(product), name, description, part_is_whole)
        if why:
            return f"contents: {why}"
    # checked after the distinguishing word above, whose reason is the more specific one ("sauce: bbq vs tomato")
    return _other_food(pw, nw, doc, attributes) or _other_package(said_head, nw, doc_words)


def _unknown_head(head: str, modifiers: list[str], name_words: list[str], doc: set[str]) -> str | None:
    """Why a head noun that no kinds table knows cannot name the object: one of its own words only when it is the
    object's noun or the object comes in a package or is reached through a part ("salad" is no salad dressing,
    "wine" may be the wine bottle); a part or package noun only through a modifier the object has ("soda can" is
    no ketchup); any other noun only when the encoder puts it near the object's own noun (`_noun_cosine`)."""
    own_head = word_forms(name_words[-1])
    if word_forms(head) & own_head:
        return None
    if word_forms(head) & doc:
        if own_head & (PARTS | PACKAGING):
            return None
        return f"noun: {head} is a word of {' '.join(name_words)}, not its noun"
    if head in PARTS | PACKAGING:
        named = modifiers
        if named and not any(word_forms(w) & doc or (word_kind(w) or frozenset()) & doc for w in named):
            return f"noun: {' '.join(named)} {head}"
        # a package holds what its modifier names: the object's noun ("ketchup bottle", "cream cheese box"), or
        # any of its words when the object is itself a package ("cookie tin"); "chocolate bar" is no pudding
        own = own_head if not own_head & (PARTS | PACKAGING) else doc
        holds = any(word_forms(w) & own or (word_kind(w) or frozenset()) & own for w in named)
        if named and head not in PARTS and not holds:
            return f"noun: {' '.join(named)} {head} holds no {name_words[-1]}"
        return None
    if _noun_cosine(head, name_words[-1]) < UNKNOWN_NOUN_MIN_COSINE:
        return f"noun: {head} vs {name_words[-1]}"
    food = own_head & CONSUMABLES or own_head & PACKAGING and any(word_forms(w) & CONSUMABLES for w in name_words[:-1])
    if food:
        # groceries are a closed vocabulary (their own words and the kinds table's synonyms): a food or drink noun
        # that is only near this one's names another food ("cheddar" is no cream cheese, "oil" no butter, "vodka"
        # no wine bottle), however close the encoder puts them
        return f"noun: {head} vs {' '.join(name_words)}"
    return None


def _unknown_owner(owners: list[str], name_words: list[str], doc: set[str]) -> str | None:
    """Why a part said of a thing no kinds table knows ("the drawer of the bookcase") is no part of the object: the
    owner is none of the object's words and the sentence encoder does not put it near any of its nouns, as for an
    unknown head noun (`UNKNOWN_NOUN_MIN_COSINE`: "kitchen" is near a cabinet, "bookcase" is not)."""
    nouns = [w for w in name_words if w not in PARTS and w not in _ATTRIBUTES] or name_words
    for w in owners:
        if w in _ATTRIBUTES | GENERIC | NOT_NOUNS | PARTS | PACKAGING or word_kind(w) is not None:
            continue  # an attribute, or a kind the kinds check has judged
        pos = getAllLemmas(w)
        if word_forms(w) & doc or pos and set(pos) != {"NOUN"}:
            continue  # the object's own word, or a word that may describe ("second", "middle", "sliding"); a word
            # unknown to the lexicon is a name
        if max(_noun_cosine(w, n) for n in nouns) < UNKNOWN_NOUN_MIN_COSINE:
            return f"owner: {w} vs {' '.join(name_words)}"
    return None


# Package nouns that say what a product comes in, by the kind of package: a jar is no box, a can no bottle. Words of
# no group ("container", "package", "pack"; "tin", said of a can and of a biscuit box alike) claim no kind of package.
_PACKAGE_KINDS: tuple[frozenset[str], ...] = (
    frozenset(["box", "carton", "case", "packet"]),
    frozenset(["can"]),
    frozenset(["bottle"]),
    frozenset(["jar"]),
    frozenset(["tub"]),
    frozenset(["bag", "pouch", "sachet"]),
)


def package_kind(word: str) -> int | None:
    return next((n for n, group in enumerate(_PACKAGE_KINDS) if word_forms(word) & group), None)


# Package nouns said of the same package ("a tin of soup" is a can of soup).
_SAME_PACKAGE = {"tin": ("tin", "can"), "can": ("can", "tin")}


def package_members(prompt: str, descriptions: list[str], kind_too: bool = False) -> set[int] | None:
    """For a prompt that is a package noun naming no kind of thing ("the carton", "a box", "the small tin"): the
    indexes of the descriptions saying their thing comes in that package ("carton of milk"); when none does, those
    saying it comes in a package of its kind (a box for "carton"). A scene with milk and juice cartons beside a box of
    butter means the cartons by "the carton", not the box (the kind alone had named all three, and "the carton that
    isn't orange juice" was two). None when the prompt is no such noun or no description says it.

    `kind_too`: a package noun that is also a kind of thing ("bottle": a wine bottle is one) names the things said
    to come in that very package as well ("the farthest of the three bottles": the ketchup, bbq sauce and salad
    dressing bottles); its kind's other packages do not count (a jar is no bottle)."""
    spoken = _words(prompt.lower())
    words = [w for w in spoken if w not in _ATTRIBUTES]
    if len(words) != 1 or (word_kind(words[0]) is not None) != kind_too:
        return None
    if kind_too and any(word_forms(w) & CONSUMABLES for w in spoken if w != words[0]):
        return None  # "the mustard bottle" ("mustard" is also a colour): what it holds says which bottle
    forms = word_forms(words[0])
    package = next((f for f in forms if f in PACKAGING), None)
    if package is None:
        return None
    said = set(_SAME_PACKAGE.get(package, (package,)))
    kind = package_kind(package)
    # whole words only: a "box-shaped cube" comes in no box
    texts = [set(d.replace(",", " ").lower().split()) for d in descriptions]
    exact = {k for k, t in enumerate(texts) if any(word_forms(w) & said for w in t)}
    if kind_too:  # what comes in one ("bottle of salad dressing"), not what holds them ("a stand that holds bottles")
        lows = [d.lower() for d in descriptions]
        came = {k for k, d in enumerate(lows) if any(re.search(rf"\b{re.escape(f)} of\b", d) for f in said)}
        return came or None
    if exact:
        return exact
    alike = {k for k, t in enumerate(texts) if kind is not None and any(package_kind(w) == kind for w in t)}
    return alike or None


def _other_package(head: str, name_words: list[str], doc_words: list[str]) -> str | None:
    """The object is (or, by its description, comes in) a package of one kind and the prompt's noun is a package of
    another ("cookie jar" for the cookies in their box, "ketchup jar" for the ketchup's bottle): another product."""
    said = package_kind(head)
    if said is None or not name_words:
        return None
    own = {k for w in [name_words[-1], *doc_words] if (k := package_kind(w)) is not None}
    if not own or said in own:
        return None
    return f"package: {head} vs {' '.join(name_words)}"


def _other_food(said: list[str], name_words: list[str], doc: set[str], attributes: frozenset[str]) -> str | None:
    """A food or drink named by its noun with a noun of its own before it that the object does not have ("peanut
    butter" for the butter, "almond milk" for the milk): another product, unless the sentence encoder puts the
    whole phrase as near the object's name as a word that only says what the product is made of or where it comes
    from ("tomato ketchup", "cow milk": `SAME_PRODUCT_MIN_COSINE`). The object named by one word has no
    distinguishing word for the multi-word check to compare with; a describing word (an adjective: "fresh",
    "salted") or an attribute claims no other product."""
    if len(said) < 2 or not name_words or not word_forms(said[-1]) & word_forms(name_words[-1]):
        return None
    if not word_forms(name_words[-1]) & CONSUMABLES:
        return None
    for w in said[:-1]:
        if w in attributes or w in GENERIC or word_forms(w) & doc or word_kind(w) is not None:
            continue  # a word of the object's own, or a kind the kinds check has judged
        pos = getAllLemmas(w)
        if pos and set(pos) != {"NOUN"}:
            continue
        phrase = f"{w} {said[-1]}"
        if _noun_cosine(phrase, " ".join(name_words)) < SAME_PRODUCT_MIN_COSINE:
            return f"food: {phrase} is not {' '.join(name_words)}"
    return None


@functools.lru_cache(maxsize=4096)
def _noun_cosine(a: str, b: str) -> float:
    va, vb = SHARED_ENCODER.encode([a, b])
    return float(va @ vb)


def own_noun_prompts(prompt: str, names: list[str]) -> dict[int, str]:
    """index into `names` -> `prompt` with each word of that name's kind put as the name's own noun ("red brick"
    -> "red block" for "block", "hob" -> "stove"), for the names where that changes the prompt: a thing scores at
    least as the prompt naming it by its own noun would. A word of the kind of another word of the name is that word
    ("vino" -> "wine" for the wine bottle)."""
    words = prompt.split()
    out = {}
    for k, name in enumerate(names):
        own = name.split()
        noun = own[-1] if own else ""
        swapped = [next((n for n in [noun, *own[:-1]] if n != w and n in (word_kind(w) or ())), w) for w in words]
        if swapped != words:
            out[k] = " ".join(swapped)
    return out


# Words that name anything at all (the kinds table's GENERIC less the class words WordNet can place: "vessel",
# "receptacle"); a class word among them would cover every object alike, which GENERIC already says.
ANYTHING = GENERIC - {"receptacle", "vessel"}


def _noun_of(words: list[str]) -> list[str]:
    """The noun a run of words ends in, longest first: "dairy product" before "product"."""
    return [" ".join(words[-2:])] + words[-1:] if len(words) > 1 else words[-1:]


def class_members(prompt: str, names: list[str]) -> set[int] | None:
    """For a prompt whose noun is a word for a class of things ("the container", "the dairy product", "the tool")
    rather than any thing's own noun: the indexes into `names` of the things WordNet files under that class (each
    alike: two dairy products in view are two matches). None when the noun is no such word: a word of the kinds
    table, a part, a package, a word naming anything, or a word no name here falls under."""
    from .lexicon.nouns import nouns

    words = [w for w in _words(prompt.lower()) if w not in _ATTRIBUTES]
    if not words:
        return None
    lexicon = nouns()
    said = _noun_of(words)
    if len(words) > 1 and words[-1] in ANYTHING:  # "the dairy thing", "the dairy item": a dairy product
        said = [f"{' '.join(words[:-1])} product", " ".join(words[:-1])]
    for noun in said:
        # "the receptacle": what receives things put in it, as "the container" (WordNet files baskets and bowls
        # under container, not under its narrower receptacle)
        noun = {"receptacle": "container", "receptacles": "containers"}.get(noun, noun)
        if word_kind(noun) is not None or noun in ANYTHING | PARTS | NOT_NOUNS:
            return None
        if package_kind(noun) is not None or any(noun in word_forms(n.split()[-1]) for n in names if n):
            return None
        if not lexicon.senses(noun):
            continue
        members = set()
        for k, name in enumerate(names):
            name_words = name.split()
            for own in _noun_of(name_words) if name_words else []:
                kin = lexicon.kinship(noun, own)
                if kin is not None:
                    if kin.broader and not kin.same and not kin.narrower:
                        members.add(k)
                    break
        return members or None
    return None
