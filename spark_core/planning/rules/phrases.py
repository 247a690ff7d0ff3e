"""Noun phrases as perception should read them: determiners and possessives tidied, an object located by what
it rests on or stands beside kept as a relation, ordinals and comparatives turned into the spatial qualifiers
perception knows ("the farther of the two bowls" -> "farthest bowl")."""

from __future__ import annotations

import re

from ...perception.qualifiers import split_relation
from ...perception.variants import KIND_OF, PACKAGING, PARTS
from .lexicon import CONTAINERS, CONTENTS, DETERMINERS, PRONOUNS, SELF_PARTS, SUBSTANCES, TABLE

# "the closer of the two mugs" -> "closest mug"; "the bowl nearer to the robot" -> "nearest bowl"
COMPARATIVES = {
    "farther": "farthest",
    "further": "farthest",
    "closer": "closest",
    "nearer": "nearest",
    "left": "leftmost",
    "right": "rightmost",
    "front": "nearest",
    "back": "farthest",
    "upper": "top",
    "lower": "bottom",
    "higher": "top",
    "taller": "top",
    "bigger": "largest",
    "larger": "largest",
    "smaller": "smallest",
}
LOCATORS = ("between", "next to", "beside", "near", "by", "on top of", "on", "in", "inside", "at", "from", "under")
_PARTICIPLE = re.compile(
    r"\b(?:(?:(?:that|which) )?(?:is|are|sits|rests|stands|lies|sit|rest|stand|lie)|sitting|resting|standing|lying|"
    r"located|placed|found|kept|stacked|perched|set|sat|parked|left|waiting|put|stored|positioned)"
    # (when it is there: "that is currently on the cabinet")
    r"(?:\s+(?:currently|now|still|presently|already|right now))?\s+"
    r"(?=(?:not\s+)?(?:" + "|".join(re.escape(x) for x in LOCATORS) + r"|to (?:the )?(?:left|right) of|in front of|"
    r"behind|(?:left|right) of)\b)"
)
# A posture said after a thing's name with nothing after it but words of how or where-ish that name no thing
# ("sitting out", "standing upright", "lying there", "out on the table"): the words go, the name stays.
_POSTURE_TAIL = re.compile(
    r"(?<=\w) (?:(?:sitting|standing|lying|resting|perched|sat|stood|parked|waiting)"
    r"(?: (?:out|there|here|up|upright|around|about|still|flat|upside down|on its side|over there|out there|"
    r"back there|by itself|alone|nearby))*|out|out there|over there)"
    r"(?=(?: (?:on|at) (?:the )?(?:table|tabletop|table top|counter)\b)?$)"
)
# "up on the cabinet", "down in the drawer", "over by the box": the particle adds nothing to where it is
_PARTICLE = re.compile(r"\b(?:up|down|over|back) (?=(?:on|onto|in|inside|on top of|at|by|near|next to|beside)\b)")
# where one thing stands relative to another, as the relation perception measures ("in front of the box": near it)
BESIDE = re.compile(
    r"\b(?:in front of|behind|to (?:the )?(?:left|right) of|on (?:the )?(?:left|right)(?: hand)? side of|alongside|"
    r"adjacent to|close to)\b"
)
# "is not sitting on": the participle adds nothing to the negated place
_NOT_PARTICIPLE = re.compile(
    r"\b(?:(?:that|which) )?(?:is |are )?not (?:sitting|resting|standing|lying|placed|located|kept|stacked|perched|set|"
    r"left|found|parked)\s+(?=(?:on|in|inside|on top of|at|by|near|next to|beside|between|under)\b)"
)
_TABLE_TAIL = re.compile(
    r"\s+(?:on|off|off of|from|at|across|along)\s+(?:the\s+)?(?:"
    + "|".join(TABLE)
    + r")\b(?!\s+(?:center|centre|middle))(?!\s+(?!and\b|then\b)[a-z])"  # "from the counter shelf": a shelf
)
# "the mug with beads", "the cup holding the marbles": the container, named by what it holds (a substance said
# stays said: the scene must show it)
_HOLDING = re.compile(
    r" (?:with|holding|containing|full of|filled with) (?:the |some |its |all the )?"
    r"(?:(?:little|tiny|small|loose|few|coloured|colored|glass|plastic|yellow|red|blue|green) )*"
    rf"(?:{'|'.join(c for c in CONTENTS if c not in SUBSTANCES)})(?: in (?:it|them))?$"
)
_CONTAINER_OF = re.compile(r"\b(carton|jar|bottle|box|can|tin|stick|pack|packet|tub|bag|cup|piece)s? of (.+)$")


def singular(word: str) -> str:
    if word.endswith("ves") and len(word) > 4:  # "shelves", "knives": the lexicon knows which keep their v
        from lemminflect import getLemma

        return getLemma(word, "NOUN")[0]
    if word.endswith("ies") and len(word) > 4:
        return word[:-3] + "y"
    if word.endswith(("xes", "ches", "shes")):
        return word[:-2]
    if word.endswith("s") and not word.endswith("ss") and len(word) > 3:
        return word[:-1]
    return word


def strip_determiners(words: str) -> str:
    return " ".join(w for w in words.replace(",", " ").split() if w not in DETERMINERS)


def possessive(text: str) -> str:
    """ "cabinet's top drawer" -> "cabinet top drawer"; "plate's centre" -> "plate"; "mug's beads" -> "mug"; "its
    beads" -> "it" (the thing named before); "its rack" -> "rack" (a thing of its own, not a part of it)."""
    own = re.fullmatch(r"(its|their|his|her|our) (.+)", text)
    if own and (own.group(2) in SELF_PARTS or own.group(2) in CONTENTS):
        return "it"
    if own and own.group(2).split()[-1] not in PARTS | PACKAGING and own.group(1) in ("its", "their"):
        return own.group(2)  # "back on its rack": the rack it belongs on, said as the thing's own
    m = re.search(r"\b([\w ]+?)'s? (.+)$", text)
    if not m:
        return text
    owner, part = m.group(1), m.group(2)
    if part in SELF_PARTS or part in CONTENTS:
        return owner
    if part.split()[-1] not in PARTS | PACKAGING and owner.split()[-1] not in DETERMINERS:
        # "the stove's bowl": not a part of the stove, the bowl on it ("the basket's can": in it)
        return f"{part} {'in' if owner.split()[-1] in CONTAINERS else 'on'} {owner}"
    return f"{owner} {part}"


def comparative(text: str) -> str:
    """ "farther of two black bowls" -> "farthest black bowl"; "bowl nearer to the robot" -> "nearest bowl"; "thing
    that is closest to you" -> "nearest thing"."""
    text = re.sub(
        r"^(.+?) (?:(?:that|which) )?(?:is|are|sits|stands|lies) (?=(?:nearer|closer|nearest|closest|farther|further|"
        r"farthest|furthest) (?:to|from) )",
        r"\1 ",
        text,
    )
    m = re.fullmatch(r"(\w+) of (?:the )?(?:two|three|both|all) (.+)", text)
    if m and m.group(1) in COMPARATIVES:
        return f"{COMPARATIVES[m.group(1)]} {' '.join(singular(w) for w in m.group(2).split())}"
    m = re.fullmatch(r"(.+?) (?:on|to|at) (?:the |your )?(left|right|back|front)(?: side)?", text)
    if m:  # "the bowl on the left" -> "leftmost bowl"; "the mug at the back" -> "farthest mug"
        word = {"left": "leftmost", "right": "rightmost", "back": "farthest", "front": "nearest"}[m.group(2)]
        return f"{word} {m.group(1)}"
    m = re.fullmatch(r"(.+?) (?:closest|nearest|closer|nearer) to (?:the )?(?!robot|you\b|me\b)(.+)", text)
    if m:  # "the bowl closest to the plate": the one near the plate
        return f"{m.group(1)} near {m.group(2)}"
    m = re.fullmatch(r"(.+?) (?:farthest|furthest|farther|further) from (?:the )?(?!robot|you\b|me\b)(.+)", text)
    if m:
        return f"{m.group(1)} not near {m.group(2)}"
    m = re.fullmatch(r"(.+?) (?:near|close to|next to|by) (?:to )?(?:the )?(?:robot|you|me)( .+)?", text)
    if m:  # "the bowl near you (by the ramekin)": the robot is no thing to be near, the nearer one is meant
        return f"nearest {m.group(1)}{m.group(2) or ''}"
    m = re.fullmatch(r"(.+?) (\w+) (?:to|from) (?:the )?(?:robot|you|me)", text)
    if m and m.group(2) in ("nearer", "closer", "nearest", "closest"):
        return f"nearest {m.group(1)}"
    if m and m.group(2) in ("farther", "further", "farthest", "furthest"):
        return f"farthest {m.group(1)}"
    return text


def locator(text: str) -> str:
    """Where an object is, as a relation perception can use: "bowl sitting on the stove" -> "bowl on stove";
    "bowl from the stove" -> "bowl on stove"; "bowl out of the top drawer" -> "bowl in top drawer"; the table
    itself says nothing ("block off the table" -> "block")."""
    # "which is standing on", "that are kept in": the relative pronoun and its verb go with the participle
    text = re.sub(r"\b(?:(?:that|which|who) )?(?:is|are) (?=\w+(?:ing|ed)\b)", "", text)
    # "the bowl (that) was on top of the cabinet": where it was is where it is until the robot moves it
    text = re.sub(
        r"\b(?:was|were|used to be) (?=(?:on|in|inside|on top of|at|by|near|next to|beside|between)\b)", "", text
    )
    # the side of another thing, which perception measures ("the bowl to the left of the plate" -> "left of")
    text = re.sub(
        r"\b(?:(?:just|right|directly|immediately) )?(?:to|on|at) (?:the )?(left|right)(?:[- ]hand)?(?: side)? of\b",
        r"\1 of",
        text,
    )
    text = BESIDE.sub("near", _PARTICLE.sub("", _NOT_PARTICIPLE.sub("not ", text)))
    text = _PARTICIPLE.sub("", text)
    # "the green block sitting out (on the table)", "the bottle standing upright", "the block sitting there": how it
    # stands, said after its name, names no other thing (perception looks for the thing alone)
    text = _POSTURE_TAIL.sub("", text)
    # on the table is the lowest place a thing can be: "the bowl not on the table" is any bowl but the lowest, "the
    # bowl on the table" (another is up on something) the lowest; "off"/"from" the table only says where it is
    table = r"(?:the )?(?:table|tabletop|table top|counter)\b(?!\s+(?:center|centre|middle))"
    text = re.sub(rf"\bnot (?:on|at) {table}", "not bottom", text)
    on_table = re.fullmatch(rf"(.+?) (?:on|at) {table}", text)
    if on_table:  # "the item furthest back on the table": the extreme one already says which
        held = on_table.group(1)
        text = held if re.search(r"\b(?:\w+most|nearest|closest|farthest|furthest)\b", held) else f"bottom {held}"
    text = _TABLE_TAIL.sub("", text)
    # "from" before a place preposition only marks the source: the preposition says where it is
    text = re.sub(r"\bfrom (?=(?:between|inside|in|under|beside|next to|on top of)\b)", "", text)
    text = re.sub(r"\bout of\b", "in", text)
    text = re.sub(r"\boff of\b|\boff\b", "on", text)
    if not re.search(r"\b(center|centre|middle)\b", text):
        text = re.sub(r"\bfrom\b", "on", text)
    return text


def _reorder_container(m: re.Match) -> str:
    return f"{m.group(2)} {m.group(1)}" if _CONTAINER_OF.search(m.group(0)) else m.group(0)


def object_phrase(words: str) -> str:
    """An object phrase for perception: determiners go; a relation to another object stays in place. A pronoun
    ("that one", "this") stays one, for the clause before to resolve."""
    if words.strip() in (*PRONOUNS, "that", "this"):
        return "that one" if words.strip() in ("that", "this") else words.strip()
    text = locator(comparative(strip_determiners(words)))
    text = _HOLDING.sub("", text)
    text = re.sub(r"'s\b", "", possessive(text) if re.search(r"\w's (?:\w+ )?\w+$", text) else text)
    text = re.sub(r"^(?:other|one) |(?<=\w) ones?$", "", text).strip()
    text = _predicative(text)
    # "block (that) is not blue", "block other than the blue one": perception keeps the blocks not blue
    text = re.sub(r"^(.+?) (?:(?:which )?(?:is|are) not|other than) (\w+)(?: ones?)?$", r"\1 not \2", text)
    if re.search(
        r"\b(between|next to|beside|near|by|on top of|on|in|inside|at|from|under|not|left of|right of|behind)\b", text
    ):
        # the object it is located by reads as a noun phrase too ("next to the box of cookies" -> "cookies box",
        # "in the top tier of the shelf" -> "in shelf top tier")
        head, relation, anchors = split_relation(text)
        if relation and len(anchors) == 1 and (" of " in anchors[0] or relation.endswith(("left of", "right of"))):
            return f"{head} {relation} {noun_phrase(anchors[0])}"
        if relation and re.search(r"\w of \w", head):  # "drawer of the cabinet behind the block": the cabinet's
            return f"{noun_phrase(head)} {relation} {' and '.join(anchors)}"
        return re.sub(r"\b(\w+) of (\w+)$", _reorder_container, text)
    return noun_phrase(text)


# Where a thing stands, said after it: a relation to another thing.
_WHERE = r"(?:behind|beyond|next to|beside|near|by|in front of|left of|right of|to the (?:left|right) of|between)"


def _predicative(text: str) -> str:
    """A relative clause with an adjective is that adjective before the noun: "peg (that) is square" ->
    "square peg" (the relative pronoun went with the determiners)."""
    return re.sub(r"^(.+?) (?:(?:that|which) )?(?:is|are) (\w+)$", r"\2 \1", text)


def noun_phrase(words: str) -> str:
    """Strip determiners and tidy "drawer of the cabinet" -> "cabinet drawer", "cabinet's drawer" -> the same,
    "the plate's centre" -> "plate"; a count goes first ("cabinet second top drawer" -> "second top cabinet
    drawer": perception reads the rank as the phrase's first word)."""
    return re.sub(
        r"^(.+?) ((?:second|third|fourth|fifth) (?:leftmost|rightmost|nearest|farthest|top|bottom))\b",
        r"\2 \1",
        _noun_phrase(words),
    )


def _noun_phrase(words: str) -> str:
    text = possessive(strip_determiners(words).strip())
    text = _predicative(re.sub(r"^(?:other|one) |(?<=\w) ones?$", "", text).strip())
    m = re.fullmatch(r"(?:contents?|beads) of (.+)", text)
    if m:
        return m.group(1)
    m = _CONTAINER_OF.search(text)
    if m and m.start() == 0:
        return f"{m.group(2)} {m.group(1)}"  # "bottle of ketchup" -> "ketchup bottle"
    m = re.fullmatch(r"(.+?) (of|on|from) (.+)", text)
    # ("the handle on the drawer" is the drawer's handle; "the plate on the cookie box" a plate where it rests)
    head = m.group(1).split()[-1] if m else ""
    located = (
        m is not None
        and m.group(2) != "of"
        and head in KIND_OF
        and head not in PARTS | set(SELF_PARTS)
        and m.group(3) not in TABLE  # ("the dirt on the counter": the counter's dirt, what is scrubbed)
    )
    if m and not located and (m.group(3).split()[-1] not in ("stove", "table") or "drawer" in m.group(1)):
        part = m.group(1)
        if part in SELF_PARTS:
            return m.group(3)
        # "drawer on the cabinet (standing) behind the block": the cabinet's drawer, where the cabinet is
        placed = re.fullmatch(rf"(.+?)(?: (?:standing|sitting|resting|placed|located))?((?: {_WHERE} .+)?)", m.group(3))
        whole, where = placed.groups() if placed else (m.group(3), "")
        return f"{whole} {part}{where}"
    return text
