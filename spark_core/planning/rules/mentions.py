"""Every thing an instruction names must be in the scene: the objects and destinations of its clauses, the
things those are located by ("the bowl next to the toaster": the toaster), and the noun phrases the parser read
past (a trailing clause, an unknown preposition: "grab the tomato sauce for the basket"). A plan is made only
when perception finds each of them; one it finds nothing for refuses the whole instruction, so an absent object
is never planned around, in any step or role."""

from __future__ import annotations

import re

from ...perception.colors import BASE_COLOURS
from ...perception.colors import SYNONYMS as COLOUR_SYNONYMS
from ...perception.lexicon.nouns import nouns
from ...perception.qualifiers import QUALIFIERS, split_relation
from ...perception.variants import MATERIALS, SHAPES, SIZES
from .frames import said_again
from .lexicon import CONTAINERS, CONTENTS, DETERMINERS, PRONOUNS, REGIONS, SPEAKERS_PLANS, SPEAKERS_REASON, TABLE
from .parse import Clause, is_pronoun
from .phrases import singular
from .rewrite import sentences
from .things import adverb_only, is_thing, names_a_thing

# Words that locate or qualify without naming a thing in the scene ("the table's centre", "the left side").
PLACE_WORDS = frozenset(
    [
        "center",
        "centre",
        "central",
        "middle",
        "left",
        "right",
        "front",
        "back",
        "side",
        "edge",
        "corner",
        "end",
        "top",
        "bottom",
    ]
    + ["robot", "you", "me", "us", "arm", "gripper", "hand", "hands", "air", "floor", "ground", "way", "rest", "rim"]
    + ["surface", "place", "position", "spot", "half", "area", "row", "line", "direction", "distance", "moment"]
    + ["time", "goal", "task", "job", "plan", "idea", "aim", "one", "ones", "other", "others", "thing", "things"]
    + ["lot", "bit", "second", "minute", "kitchen", "scene", "workspace", "world", "room", "camera", "view"]
    + ["inside", "outside", "interior", "contents", "content", "upright", "same", "rest", "whole", "two", "three"]
    + ["underneath", "beneath", "below", "above", "atop"]
    + ["insides", "belly", "hollow", "innards"]
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
    + ["per", "each"]
)
# Words that describe a thing without naming it: a phrase is about a thing the clauses name when it shares a noun.
ATTRIBUTES = frozenset([*BASE_COLOURS, *COLOUR_SYNONYMS, *MATERIALS, *SHAPES, *SIZES])
_DET = re.compile(r"\b(?:the|a|an|some|my|your|this|these|those) ")
# The robot's own parts, said to place a thing relative to the robot ("further from the robot's base", "on your
# left"): no thing in the scene, nothing perception could look for.
ROBOT_PARTS = frozenset(
    ["base", "arm", "arms", "gripper", "hand", "hands", "wrist", "camera", "body", "claw", "end", "grip", "grasp"]
    + ["fingers", "finger", "jaws", "pincers"]
)
_ARM_WORDS = frozenset(["arm", "arms", "gripper", "grippers", "hand", "hands", "claw", "fingers"])
_ROBOT_OWNERS = frozenset(["robot", "robot's", "robots", "your", "my", "its"])


def _of_the_robot(words: list[str]) -> bool:
    """ "robot's base", "robot base": the robot's own part."""
    return len(words) >= 2 and words[0].removesuffix("'s") in ("robot", "robots") and words[-1] in ROBOT_PARTS


def anchors(phrase: str) -> list[str]:
    """The things `phrase` locates its object by ("black bowl next to plate" -> ["plate"]; "bowl between plate
    and ramekin" -> both), without places that are no object ("table center")."""
    head, relation, found = split_relation(phrase)
    # a thing after a preposition perception does not measure ("the plate under the lamp", "the bowl with a ladle in
    # it", "the peg behind the toolbox"): it locates or describes the object, so it must be there too
    m = _OTHER_PREP.search(head if relation else phrase)
    if m:
        found = [*found, _OTHER_PREP.split(m.group(2))[0].strip()]
    # things joined to the phrase's own by "and" ("the plate and mind the vase"): each is a thing of its own
    found += re.split(r"\s+(?:and|or|plus|as well as|along with|together with)\s+", head)[1:]
    return [
        a
        for a in dict.fromkeys(found)
        if a and not set(a.split()) - {"of", "the"} <= PLACE_WORDS and a not in PRONOUNS and names_a_thing(a)
    ]


_OTHER_PREP = re.compile(
    r"\b(with|under|underneath|below|beneath|behind|above|against|opposite|alongside|using|holding|containing|"
    # a clause the phrase swallowed ("the plate after you move the kettle"): what it names is named all the same
    r"after|before|once|while|until|unless|when)\s+"
    r"(?:the |a |an |some |its |their )?([a-z][a-z ]*)$"
)


def clause_mentions(clauses: list[Clause]) -> list[str]:
    """Object phrases of the clauses and the anchors of their relations, in order, each once."""
    out: dict[str, None] = {}
    for c in clauses:
        for p in (c.obj, c.target, c.tool, c.source):
            if not p or is_pronoun(p):
                continue
            if p == c.obj and c.action == "pour" and c.source and c.source != c.obj:
                continue  # what is poured out of the source (its beads, its water) is the source's to hold
            if c.action == "pour" and p == c.source and p.split()[-1] in CONTENTS:
                continue  # contents named without their container: poured from the container found (planner.py)
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
    for sentence in (_ASIDE.sub("", _CLOSING_REMARK.sub("", s)) for s in sentences(instruction)):
        for m in _DET.finditer(sentence):
            words: list[str] = []
            # (a comma, colon or dash ends the phrase: "the little ramekin: place it ...")
            for w in re.sub(r"([,:;]|\s-+\s)", " , ", sentence[m.end() :]).split():
                if w in _NP_STOP or w == "," or not re.fullmatch(r"[a-z][a-z'-]*", w) or len(words) == 3:
                    break
                if w not in DETERMINERS:
                    words.append(w.removesuffix("'s"))
            if not words:
                continue
            head = words[-1]
            if _of_the_robot(words) or (m.group(0).strip() in ("your", "my") and head in ROBOT_PARTS):
                continue  # where the robot is ("further from the robot's base", "your arm")
            if words[0] in _ARM_WORDS and head in (*_ARM_WORDS, "home"):
                continue  # the robot's own arm ("then send the arm home")
            if {head, singular(head)} & PLACE_WORDS or head in REGIONS or set(words) & set(CONTENTS):
                continue  # a place, or what a container holds ("so the beads fall in")
            if not names_a_thing(" ".join(words)):
                continue  # no thing at all ("the gap", "a sec", "the end"): nothing perception could look for
            if any({w, singular(w)} & said for w in words if w not in ATTRIBUTES):
                continue
            out.setdefault(" ".join(words), None)
    return list(out)


# Closed-class and instruction words that are no thing in the scene, whatever the lexicon says ("pick" is a noun
# too): the planner's own verbs, fillers, directions and goal words, and the words that only qualify or count.
def _closed_words() -> frozenset[str]:
    from .lexicon import COPULAS, DIRECTIONS, FILLERS, HELD, MODALS, PARTICIPLES, STATE_ACTIONS, VERBS
    from .qualify import EXTREMES, RANKS, SIDES

    phrases = [f for forms in VERBS.values() for f in forms] + list(FILLERS) + list(COPULAS) + list(MODALS)
    phrases += [f for forms in DIRECTIONS.values() for f in forms] + list(HELD) + list(PARTICIPLES)
    phrases += [s for s, _ in STATE_ACTIONS] + list(EXTREMES) + list(RANKS) + list(SIDES) + list(TABLE)
    return frozenset(w for p in phrases for w in re.findall(r"[a-z]+", p)) | PLACE_WORDS | _NP_STOP


# Nouns that name no object perception could look for: what is said about the task, the robot or the speaker,
# amounts and ways ("any chance you could", "from the robot's point of view", "in one go", "the rest").
ABSTRACT = frozenset(
    ["chance", "point", "view", "favour", "favor", "go", "turn", "step", "steps", "please", "thanks", "ok", "okay"]
    + ["hey", "hi", "hello", "sorry", "bit", "lot", "kind", "sort", "type", "sense", "need", "want", "wish", "request"]
    + ["instruction", "instructions", "command", "everything", "anything", "something", "nothing", "all", "rest"]
    + ["same", "other", "another", "each", "either", "neither", "nor", "both", "ones", "none", "end", "start"]
    + ["beginning", "finish", "later", "today", "now", "moment", "sec", "second", "seconds", "minute", "minutes"]
    + ["quick", "mind", "care", "attention", "way", "fashion", "manner", "pose", "angle", "level", "height"]
    + ["inch", "inches", "cm", "mm", "centimetre", "centimetres", "centimeter", "centimeters", "metre", "meter"]
    + ["order", "sequence", "first", "last", "next", "number", "count", "one", "two", "three", "four", "five"]
    + ["please", "cheers", "ta", "thank", "lad", "mate", "buddy", "pal", "friend", "bot", "robot", "machine"]
    + ["setup", "set", "scene", "layout", "workspace", "workbench", "bench", "desk", "surface", "stuff", "thing"]
    + ["someone", "somebody", "anyone", "anybody", "everyone", "everybody", "nobody", "your", "yours", "mine"]
    # keyboard slips and interjections the lexicon does not know ("dont", "hmm", "atop")
    + ["dont", "cant", "wont", "didnt", "isnt", "hmm", "hmmm", "umm", "um", "uh", "pls", "plz", "thx", "atop"]
)


def stray_nouns(instruction: str, clauses: list[Clause]) -> list[str]:
    """Single nouns of the instruction that no phrase the planner looks for holds: a thing said where the parser
    does not read things ("pour it with a ladle", "the plate under the lamp", "... and the kettle too"). Each must
    be in the scene like any other thing the instruction names. A word the lexicon also knows as a verb counts
    only after a determiner or a describing word ("with the wrench", not "fish it out")."""
    looked = [*clause_mentions(clauses), *(c.obj for c in clauses if c.obj), *read_past(instruction, clauses)]
    said = _words(looked)
    closed = _closed_words()
    out: dict[str, None] = {}
    for sentence in sentences(instruction):
        words = re.findall(r"[a-z]+(?:'s)?", _ASIDE.sub("", _CLOSING_REMARK.sub("", sentence)))
        for i, raw in enumerate(words):
            w = raw.removesuffix("'s")
            if len(w) < 3 or {w, singular(w)} & (said | closed | ABSTRACT | ATTRIBUTES) or w in CONTENTS:
                continue
            if w in DETERMINERS or w in PRONOUNS or not is_thing(w) or adverb_only(w) or said_again(w):
                continue  # (a verb said again, "restack", is no thing either)
            if nouns().names_no_thing(w):
                continue  # a person, a group, an act ("for grandma", "the crowd goes wild"): nothing to look for
            before = words[i - 1].removesuffix("'s") if i else ""
            if w in ROBOT_PARTS and i and words[i - 1] in _ROBOT_OWNERS:
                continue  # the robot's own part ("the robot's base", "your arm")
            if _not_only_noun(w) and not (
                before in _NOUN_BEFORE or before in ATTRIBUTES or words[i - 1].endswith("'s")
            ):
                continue  # "fish it out", "once it is in": a verb or an adverb here, a noun only after "the"
            out.setdefault(w, None)
    return list(out)


# A remark that closes the request by naming it ("..., that's the target", "... - that's what I'm after", "..., is
# what I want"): it names the request, not a thing.
# An aside after the request, no part of it ("..., since it's going back to the fridge", "..., i need to get at
# what's inside", "..., (carefully) so the stack doesn't tip"): the parser drops it (rewrite._TRAILING), and what it
# names need not be in the scene.
_ASIDE = re.compile(
    r",?\s*(?:(?:since|because) (?:it|they|that|this|i|we|you)\b|(?:i|we) (?:need|want|have) to "
    r"(?:get|reach|see|look|check)\b|(?:carefully|gently|slowly) so\b|"
    r"so (?:that )?(?:it|they|the [a-z]+) (?:does|do|will|would|is|are|can|could) not\b|"
    rf"{SPEAKERS_PLANS}|"
    # how thoroughly a cleaning goal is met ("..., every last speck", "..., not a crumb left"): the dirt, no thing
    r"(?:every|each|evry) (?:last |single )?(?:speck|bit|crumb|trace|spot|smudge)s?\b|"
    r"not (?:a|one|a single) (?:speck|bit|crumb|trace|spot|smudge)\b|"
    # how not to do it, after the request ("..., don't leave any stains behind"); not a thing left alone
    r"(?:(?<=[,-]) *(?:and |but )?|\s+and\s+)"
    r"(?:(?:do not|don't|dont|never|try not to|careful not to|be careful not to) "
    r"(?!touch|move|take|grab|use|pick|lift|get|put|place|disturb|bother|mess|need)[a-z]+\b|"
    rf"{SPEAKERS_REASON})).*$"
)
_CLOSING_REMARK = re.compile(
    r"(?:\b(?:that|this) (?:is|will be|should be) |(?:,|-)\s*(?:is|are) )(?:the (?:target|goal|aim|idea|plan|"
    r"end state|final state|end result|result|outcome|arrangement|state)|what (?:i|we) (?:am|are) (?:after|"
    r"asking for|going for|looking for)|what (?:i|we) (?:want|need|mean|would like))\b.*$"
)
_NOUN_BEFORE = frozenset(
    ["the", "a", "an", "my", "your", "his", "her", "its", "their", "our", "this", "that", "these", "those", "some"]
    + ["any", "each", "every", "no", "another", "other"]
)


def _not_only_noun(word: str) -> bool:
    """The lexicon knows `word` as something besides a noun (a verb, an adverb, an adjective)."""
    from lemminflect import getAllLemmas

    return bool(set(getAllLemmas(word)) - {"NOUN"})


def foreign_modifiers(phrases: list[str], inventory: tuple[str, ...]) -> list[str]:
    """Words before a phrase's head noun that name a thing of their own, which nothing the scene holds is called by:
    a kind of thing other than the head's ("the toaster plate" where there is no toaster) or a name the lexicon does
    not know ("the lego block", a brand). Perception grounds such a phrase by its head noun, so the thing the
    modifier names would go unchecked; like any thing the instruction names it must be there. A word that says
    what a thing is for or made of and names no kind ("dinner plate", "porcelain pot") is no such claim, and nor is
    what a container holds ("the cup of beads": it may be out of sight inside). Checked
    against what perception can list of the scene (`inventory`: the names, their words and the kinds table's
    other words for them); with no list, nothing is checked here."""
    from lemminflect import getAllLemmas

    from ...perception.variants import KIND_OF, SPELLINGS

    if not inventory:
        return []

    def forms(word: str) -> set[str]:  # "cookies": cookie (not only "cooky"); "barbecue": bbq
        out = {word, singular(word), word[:-1] if word.endswith("s") and len(word) > 3 else word}
        return out | {SPELLINGS[f] for f in out if f in SPELLINGS}

    def kind(word: str) -> frozenset[str]:
        return frozenset().union(*(KIND_OF.get(f, frozenset()) for f in forms(word)))

    held: set[str] = set()
    for name in inventory:
        for w in re.sub(r"\s*\(\d+\)$", "", name).lower().split():
            held |= forms(w) | kind(w)
    skip = ATTRIBUTES | frozenset(QUALIFIERS) | PLACE_WORDS | _closed_words() | ABSTRACT
    out: dict[str, None] = {}
    for phrase in phrases:
        if not phrase or is_pronoun(phrase):
            continue
        head = re.split(r"\s+not\s+", split_relation(phrase)[0])[0]
        words = re.findall(r"[a-z]+", head.lower())
        if len(words) < 2:
            continue
        if forms(words[-1]) & set(CONTAINERS):
            continue  # "the cup of little balls": what a container holds may be out of sight inside it
        own = kind(words[-1]) | forms(words[-1])
        for w in words[:-1]:
            if w in skip or singular(w) in skip or w in DETERMINERS or len(w) < 3:
                continue
            named = kind(w)
            if not named and getAllLemmas(w):
                continue  # a word the lexicon knows that is no kind: what it is for or made of ("dinner plate")
            if forms(w) & held or named & own:
                continue
            out.setdefault(w, None)
    return list(out)
