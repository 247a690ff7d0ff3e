"""An order-free reading of a one-step instruction: the intent found anywhere in the sentence, every noun mention
with its modifiers, and each mention's role from the words attached to it, not from where it stands.

The rule parser (parse.py) reads clauses left to right; when it refuses, or leaves a thing the sentence names
unused, the planner tries these readings instead (planner.py). A mention's role comes from its own preposition
("in/into/on/onto/to/atop" a destination, "from/out of/off" where the thing is now, "with/using" a tool, "next to/
beside/near/between" a thing it is located by); a mention with none is the thing acted on. When a destination
preposition might also say where the thing stands ("the bowl on the stove onto the plate"), each way of reading it
is a reading of its own, and the scene decides (planner.py accepts exactly one that grounds).

A reading is offered only when every word of the sentence is accounted for: part of a mention, or a word that
names no thing (a verb, a preposition, a filler, a qualifier). A noun left over, known or not ("the rice", a
typo), gives no reading, so a thing the scene may not hold is never read past here."""

from __future__ import annotations

import itertools
import re
from dataclasses import dataclass, replace

from lemminflect import getAllLemmas

from ...perception.colors import BASE_COLOURS
from ...perception.variants import GENERIC, KIND_OF, PACKAGING
from .asides import aside_positions
from .frames import goes_to, leading_verb, said_again
from .framing import unframed
from .lexicon import CONTAINERS, CONTENTS, DETERMINERS, FILLERS, PARTICIPLES, REGIONS, STATE_ACTIONS, TABLE, VERBS
from .mentions import ABSTRACT, ATTRIBUTES, PLACE_WORDS, _closed_words
from .parse import Clause, is_pronoun
from .phrases import object_phrase, singular
from .qualify import negations, neither_nor, ordinals
from .rewrite import CONTRACTIONS
from .shapes import as_moved
from .stepwise import steps
from .things import adverb_only, is_thing, is_verb

# A mention's own preposition -> its role. Longest first when matched.
_ROLE_OF: dict[str, tuple[str, str | None]] = {
    "on top of": ("dest", "on"),
    "onto": ("dest", "on"),
    "on to": ("dest", "on"),
    "atop": ("dest", "on"),
    "over": ("dest", "on"),
    "on": ("dest", "on"),
    "into": ("dest", "in"),
    "inside of": ("dest", "in"),
    "inside": ("dest", "in"),
    "within": ("dest", "in"),
    "in": ("dest", "in"),
    "to": ("dest", None),  # into a container, onto anything else
    "out of": ("source", "in"),
    "off of": ("source", "on"),
    "off": ("source", "on"),
    "from": ("source", "on"),
    "with": ("tool", None),
    "using": ("tool", None),
    "next to": ("near", "next to"),
    "beside": ("near", "beside"),
    "near": ("near", "near"),
    "between": ("near", "between"),
}
_PREPS = sorted(_ROLE_OF, key=len, reverse=True)
# Words that end a mention without a role of their own.
_BREAK = frozenset(
    ["and", "or", "but", "then", "so", "that", "which", "who", "is", "are", "be", "was", "were", "it", "them"]
    + ["should", "must", "will", "would", "can", "could", "goes", "go", "belongs", "belong", "needs", "need", "not"]
    + ["up", "down", "out", "away", "back", "please", "too", "there", "here", "where", "whichever", "want", "like"]
    + ["have", "has", "get", "gets", "ends", "end", "sits", "sit", "stays", "stay", "meant", "supposed", "to", "of"]
    + ["at", "for", "across", "along", "around", "until", "till", "if", "when", "while", "as", "than"]
    # prepositions whose thing locates another in a way perception does not measure: a mention of its own
    + ["under", "underneath", "beneath", "below", "behind", "above", "against", "opposite", "via", "through"]
)
# Words that pick a thing out by what it is not, or say what to leave be: the rule parser's to read, never dropped.
_NEGATION = frozenset(
    ["not", "no", "never", "neither", "nor", "except", "other", "another", "alone", "leave", "instead", "rather"]
    + ["without", "but", "besides", "apart", "else", "n't", "isn't", "aren't", "don't", "doesn't"]
)
# Which way, said after the thing ("shove the cube forward ..."): no part of its name.
_WAYS = frozenset(["forward", "forwards", "backward", "backwards", "ahead", "sideways"])
# Words that join a mention to the robot, not to a thing in the scene: "further from the robot" qualifies.
_ROBOT = frozenset(["robot", "you", "me", "us", "base", "arm", "gripper"])
_COMPARED = {"further": "farthest", "farther": "farthest", "closer": "nearest", "nearer": "nearest"}
# A stated goal: a wish or a state, with no verb of the planner's own.
_GOAL_WORDS = frozenset(
    ["belongs", "belong", "goes", "go", "should", "must", "want", "wants", "needs", "need", "meant", "supposed"]
    + ["end", "ends", "wind", "winds", "sit", "sits", "rest", "rests", "stay", "stays", "like", "ought", "lives"]
)
# What a participle may say is done to the thing: moved somewhere, or poured.
_MOVES = frozenset(["put", "stack", "push", "pour"])
# A question about the scene, not a request (a request put as a question asks with "could you", "can the ...").
_QUESTION = frozenset(["how", "what", "why", "who", "whose", "when", "does", "did", "do", "whether"])


@dataclass(frozen=True)
class Mention:
    phrase: str  # as perception reads it (object_phrase): determiners gone, qualifiers in its words
    role: str  # "thing" | "dest" | "source" | "tool" | "near" | "pronoun"
    relation: str | None  # on | in | None (dest, source); the relation word (near)
    start: int  # token index: which mention a locator follows
    end: int = 0  # token index after its last word


def _tokens(instruction: str) -> list[str]:
    text = instruction.lower().replace("\u2019", "'")
    for short, long in CONTRACTIONS.items():
        text = re.sub(rf"\b{re.escape(short)}\b", long, text)
    text = re.sub(r"(\w)'s\b(?= (?:meant|supposed|going|got|to|in|on|at)\b)", r"\1 is", text)  # "block's meant"
    text = re.sub(r"\s*(?:-+>|=>|\u2192)\s*", " , to ", text)  # "ketchup -> basket": where it goes
    # where an ordinal counts from ("the second drawer counting from the top"): the side, as "from the top" says
    text = ordinals(
        re.sub(r"\b(?:counting|starting|going|numbering) (?=from (?:the )?(?:top|bottom|left|right)\b)", "", text)
    )  # "the second drawer from the top" -> "the second top drawer", as the rule parser reads it
    # ruling one out, as "<kind> not <what rules it out>" (the rule parser's forms: "the other bowl, not the one on
    # the stove" -> "the bowl not on the stove"); "the bowl that is not on ..." alike
    text = re.sub(r"\b(?:that|which) (?:is|are) not\b", "not", negations(neither_nor(text)))
    text = re.sub(r"[,;:!?.()\"\u2013\u2014]|\s-\s", " , ", text)
    tokens = text.split()
    asides = aside_positions(tokens, _closed)  # "..., no need to be gentle about it": says how, names nothing
    out: list[str] = []
    for n, t in enumerate(tokens):
        if n not in asides:
            out.append(t)
        elif not out or out[-1] != ",":
            out.append(",")  # an aside leaves a break where it was
    return out


def _verbs() -> list[tuple[list[str], str]]:
    forms = [(f.split(), a) for a, fs in VERBS.items() for f in fs]
    forms += [(s.split(), a) for s, a in STATE_ACTIONS if a in ("open", "close") and " " not in s]
    return sorted(forms, key=lambda x: -len(x[0]))


def intent(tokens: list[str]) -> tuple[set[str], bool]:
    """The actions the sentence's verbs name (anywhere), or its participles ("..., poured out of the mug",
    "the cube stacked on ..."), and whether it states a goal without one."""
    actions: set[str] = set()
    for i in range(len(tokens)):
        for form, action in _verbs():
            if tokens[i : i + len(form)] == form:
                actions.add(action)
                break
        else:
            if tokens[i] in PARTICIPLES and PARTICIPLES[tokens[i]] in _MOVES:
                actions.add(PARTICIPLES[tokens[i]])
            elif said_again(tokens[i]):
                actions.add(said_again(tokens[i]) or "")
    goal = bool(set(tokens) & _GOAL_WORDS) or any(t in ("into", "onto", "atop", "inside") for t in tokens)
    goal = goal or any(a == "on" and b == "to" for a, b in zip(tokens, tokens[1:]))  # "on to the plate": onto
    return actions, goal


def _closed(word: str) -> bool:
    """A word that names no thing in the scene."""
    w = word.removesuffix("'s")
    return (
        w in _closed_words()
        or w in ABSTRACT
        or w in DETERMINERS
        or w in _BREAK
        or w in _COMPARED
        or w in _ROBOT
        or singular(w) in PLACE_WORDS
        or not w.isalpha()
        or not is_thing(w)
        or adverb_only(w)
    )


def _participle(word: str) -> bool:
    """A verb's -ing or -ed form ("sitting", "placed"): said after the noun with a place after it, it ends the
    noun phrase ("the red block sitting in the bowl"); before a noun it names ("the baking tray") it does not."""
    return word.endswith(("ing", "ed")) and "VERB" in getAllLemmas(word)


def preposition_at(tokens: list[str], i: int) -> tuple[str, str | None, int]:
    """The role and relation the preposition starting at token `i` gives the phrase after it (_ROLE_OF), and the
    index after the preposition; ("thing", None, i) when none starts there. The longest preposition wins."""
    for p in _PREPS:
        words = p.split()
        if tokens[i : i + len(words)] == words:
            role, relation = _ROLE_OF[p]
            return role, relation, i + len(words)
    return "thing", None, i


def _starts_preposition(tokens: list[str], k: int) -> bool:
    """A preposition other than "of" starts at token `k`: it ends the noun phrase before it."""
    return any(tokens[k : k + len(p.split())] == p.split() for p in _PREPS if p != "of")


def _ends_phrase(tokens: list[str], k: int) -> bool:
    """Nothing of a noun phrase follows: the end, a comma or a preposition ("sitting in the bowl")."""
    return k >= len(tokens) or tokens[k] in (",", "at", "by") or any(tokens[k] == p.split()[0] for p in _PREPS)


def _verb_spans(tokens: list[str]) -> set[int]:
    out: set[int] = {i for i, t in enumerate(tokens) if said_again(t)}
    for i in range(len(tokens)):
        for form, _action in _verbs():
            if tokens[i : i + len(form)] == form:
                out |= set(range(i, i + len(form)))
                break
    return out


def mentions(instruction: str) -> list[Mention] | None:
    """Every noun mention with its role; None when a word that names a thing is left outside every mention."""
    return _mentions(instruction)[0]


def _mentions(instruction: str, later: bool = False) -> tuple[list[Mention] | None, str]:
    """The mentions, or None and why there are none (`why_no_reading`). In a `later` step of several, "it" and
    "them" are mentions too: the thing acted on, or where it goes ("stack the red cube on it"), said before."""
    tokens = _tokens(instruction)
    if set(tokens) & (_NEGATION - {"not"}) or any(t.endswith("n't") for t in tokens):
        return None, "negation"
    if set(tokens) & _QUESTION:
        return None, "question"  # a question about the scene ("how hot does ... get"): no request
    if any(a == b for a, b in zip(tokens, tokens[1:])):
        return None, "repeated word"  # words said twice over
    verbs = _verb_spans(tokens)
    fillers = {w for f in FILLERS for w in f.split()}
    out: list[Mention] = []
    i = 0
    while i < len(tokens):
        role, relation, j = preposition_at(tokens, i)
        k = j
        while k < len(tokens) and tokens[k] in DETERMINERS:
            k += 1
        span: list[str] = []
        while k < len(tokens) and k not in verbs and tokens[k] != "," and (tokens[k] not in _BREAK or span):
            if span and tokens[k] == "not":
                ruled, k = _ruled_out(tokens, k, verbs)
                span += ruled
                break
            if tokens[k] in _BREAK or _starts_preposition(tokens, k):
                break
            if span and tokens[k] in DETERMINERS:
                break  # "love the pear": a word before a determiner is no part of the phrase after it
            if span and _participle(tokens[k]) and _ends_phrase(tokens, k + 1):
                break  # "the red block sitting in the bowl": where it sits, not its name
            span.append(tokens[k])
            k += 1
        if relation == "between" and span and tokens[k : k + 1] == ["and"]:
            k = _second_of_between(tokens, k + 1, verbs, span)  # "between the plate and the ramekin": both
        if span and span[-1] in ("one", "ones") and len(span) > 1:
            head = next((_head(m.phrase) for m in reversed(out) if m.role != "pronoun"), None)
            if head is None:
                return None, "'one' with no noun before it"  # "the red one" with no noun said before it
            span = [*span[:-1], head]
        while span and (span[-1] in fillers or span[-1] in ABSTRACT or adverb_only(span[-1]) or span[-1] in _WAYS):
            span.pop()  # "the plate please"
        # a describing word names the thing when it ends the phrase ("the lemon", "the orange": fruit, not colours)
        heads = [w for n, w in enumerate(span) if not _closed(w) and (w not in ATTRIBUTES or _names(w, n, span))]
        if later and tokens[j : j + 1] in (["it"], ["them"]) and role in ("thing", "dest"):
            out.append(Mention("it", role, relation, i, j + 1))
            i = j + 1
            continue
        if heads and (role != "source" or " ".join(span) not in TABLE):
            if set(span) & _ROBOT:
                # "between the robot and the plate": a place, not a thing; the rule parser's to read
                return None, "robot in a mention"
            phrase = object_phrase(" ".join(span))
            out.append(Mention(phrase, role, relation, i, k))
            i = k
            continue
        if span and role == "source" and " ".join(span) in TABLE:
            i = k
            continue
        if k > i and span and not heads:
            i = k  # words that name nothing ("further", "over there")
            continue
        i = max(i + 1, j)
    left = _uncovered(tokens, out)
    if left is not None:
        return None, left
    inside = {n for m in out for n in range(m.start, m.end)}
    if any(t == "not" and n not in inside for n, t in enumerate(tokens)):
        return None, "negation"  # a "not" that rules out no thing of a mention ("do not put ...")
    return out, ""


_RULED_BY = ("on top of", "next to", "on", "in", "inside", "beside", "near", "between")


def _ruled_out(tokens: list[str], k: int, verbs: set[int]) -> tuple[list[str], int]:
    """ "not", a relation if any, and the words of what it rules out ("not on the stove", "not yellow"), from
    token k; with the index after them. Nothing when no word follows (the "not" then stands alone: refused)."""
    out, n = ["not"], k + 1
    for p in _RULED_BY:
        if tokens[n : n + len(p.split())] == p.split():
            out += p.split()
            n += len(p.split())
            break
    while n < len(tokens) and tokens[n] in DETERMINERS:
        n += 1
    start = n
    while n < len(tokens) and n not in verbs and tokens[n] != "," and tokens[n] not in _BREAK:
        if _starts_preposition(tokens, n):
            break
        out.append(tokens[n])
        n += 1
    return (out, n) if n > start else ([], k)


def _second_of_between(tokens: list[str], k: int, verbs: set[int], span: list[str]) -> int:
    """The second thing of "between A and B", added to `span` as "A and B"; the index after it."""
    while k < len(tokens) and tokens[k] in DETERMINERS:
        k += 1
    more: list[str] = []
    while k < len(tokens) and k not in verbs and tokens[k] != "," and tokens[k] not in _BREAK:
        if _starts_preposition(tokens, k):
            break
        more.append(tokens[k])
        k += 1
    span += ["and", *more] if more else []
    return k


def _listed_into(things: list[Mention], tokens: list[str]) -> bool:
    """Two things listed with a comma between them and nothing else, the second a container ("ketchup, basket")."""
    first, second = things
    return tokens[first.end : second.start] == [","] and _head(second.phrase) in CONTAINERS


def _region(phrase: str) -> bool:
    """A flat area things are pushed into ("zone", "patch", "target")."""
    head = _head(phrase)
    return head in REGIONS or "area" in KIND_OF.get(singular(head), frozenset())


def _head(phrase: str) -> str:
    """The head noun of a mention's phrase: its last word before what rules one out ("carton not orange juice")."""
    return re.split(r"\s+not\s+", phrase)[0].split()[-1]


def _names(word: str, n: int, span: list[str]) -> bool:
    """A describing word that ends its phrase and is a thing besides a colour names the thing ("the lemon")."""
    return n == len(span) - 1 and word not in BASE_COLOURS


def _uncovered(tokens: list[str], found: list[Mention]) -> str | None:
    """None when every word that names a thing is in some mention (outside them only words that name none, and no
    verb the planner has no action for); else what the first word left over is."""
    inside = {n for m in found for n in range(m.start, m.end)}
    verbs = _verb_spans(tokens)
    for n, t in enumerate(tokens):
        if n in inside or n in verbs:
            continue
        if t in BASE_COLOURS:
            # "the blue one": a colour said of a kind named elsewhere; a colour describing nothing is a word salad
            # ("drawer the open blue sideways of quickly")
            said_of = tokens[n + 1 : n + 2] in (["one"], ["ones"]) or n > 0 and tokens[n - 1] in DETERMINERS
            if said_of or any(t in m.phrase.split() for m in found):  # "the blue (one)": a thing said by its colour
                continue
            return f"colour left over: {t}"
        if not _closed(t):
            return f"noun left over: {t}"
        if _unknown_verb(t):
            return f"unknown verb: {t}"
    return None


def _unknown_verb(word: str) -> bool:
    """A verb the planner has no action for ("eat", "love"): what it asks is unknown, so nothing is read."""
    known = _closed_words() | _BREAK | _GOAL_WORDS | ABSTRACT | _ROBOT | {w for f in FILLERS for w in f.split()}
    return word not in known and word not in DETERMINERS and is_verb(word) and not adverb_only(word)


# Where a thing is said to be from the robot's side of the table, right after the thing ("the block on your left",
# "the bowl closest to you", "the cube to the robot's right"): a qualifier perception reads ("left", "nearest").
_SIDE = re.compile(
    r"^(?:(?:that|which) (?:is|are) |, )?(?:(?:on|to|at|towards?) (?:your|the robot's|the) (left|right)(?: hand)?"
    r"(?: side)?|(nearest|closest|nearer|closer) (?:to )?(?:you|the robot|robot)|(farthest|furthest|further|farther)"
    r" (?:away )?from (?:you|the robot|robot))\b"
)
_SUPERLATIVE = {"nearer": "nearest", "closer": "nearest", "further": "farthest", "farther": "farthest"}


def _sided(m: Mention, tokens: list[str]) -> Mention:
    """The mention with the robot-relative qualifier said right after it, if any ("block on your left" -> "left
    block")."""
    said = _SIDE.match(" ".join(tokens[m.end :]))
    if not said or m.role == "pronoun":
        return m
    word = next(g for g in said.groups() if g)
    word = _SUPERLATIVE.get(word, word)
    return m if word in m.phrase.split() else replace(m, phrase=f"{word} {m.phrase}")


def _qualified(phrase: str, tokens: list[str]) -> str:
    """ "whichever block is further from the robot": the comparative said of the robot qualifies the thing."""
    text = " ".join(tokens)
    for word, superlative in _COMPARED.items():
        if re.search(rf"\b{word} (?:from|to) (?:the )?(?:robot|you|me|us)\b", text) and superlative not in phrase:
            return f"{superlative} {phrase}"
    return phrase


def readings(instruction: str) -> list[list[Clause]]:
    """Each one-step reading whose roles are complete: one thing, and a destination when the intent needs one."""
    return _readings(instruction)[0]


def why_no_reading(instruction: str) -> str:
    """Why the order-free reader offers no reading ("" when it offers one): the condition that stopped it."""
    return _readings(instruction)[1]


# Where one step ends and the next begins: a word that orders them.
_STEPS = re.compile(
    r"\s*[,;.]?\s*\b(?:and then|then|after that|afterwards|and after that|once done|once that is done"
    r"|next(?! to))\b\s*,?\s*|\s*;\s*"
)
_MAX_COMBINATIONS = 8
# Letting go of the thing or keeping hold of it, said after a step that carries it ("..., and let go of it above the
# bowl", "... and keep hold of it"): what the step before does anyway, no step of its own.
_NO_STEP = re.compile(
    r"^(?:let go of|let go|release|keep hold of|keep holding|keep a hold of|hold on to|hold onto)"
    r"(?: (?:it|them)\b|(?=\s*[.!]?\s*$))"  # or said alone ("...; 3) release.")
)
_HOLD_FORMS = ("let go", "release", "keep hold", "keep holding", "keep a hold", "hold on to", "hold onto")


def _clause_split() -> re.Pattern[str]:
    """Where a step holds several clauses, each with a verb of its own ("pick the block up, carry it over to the
    bowl and let go of it"): a comma or "and" before one of the planner's verbs, or before letting go."""
    forms = sorted({f for fs in VERBS.values() for f in fs} | set(_HOLD_FORMS), key=len, reverse=True)
    return re.compile(r"\s*(?:,\s*(?:and\s+)?|\s+and\s+)(?=(?:" + "|".join(map(re.escape, forms)) + r")\b)")


_CLAUSES = _clause_split()


def _steps(instruction: str) -> tuple[list[str], bool]:
    """The steps of an instruction: parts a word orders ("then"), each split into clauses with verbs of their own;
    a clause that only lets go of or keeps hold of what the clause before carried is no step (and whether one was
    dropped)."""
    out: list[str] = []
    dropped = False
    for part in _STEPS.split(instruction.lower().replace("that's", "that is")):
        for clause in _CLAUSES.split(part):
            if not clause.strip():
                continue
            if out and (_held_only(clause.strip(), out) or _describes_it(clause.strip())):
                dropped = True
            else:
                out.append(clause)
    return out, dropped


def _describes_it(clause: str) -> bool:
    """A remark that says what "it" looks like and names no kind ("it's the flat box", "it is the small red one"):
    which thing was meant, said again; no step."""
    m = re.fullmatch(r"(?:it|this|that)(?: is|'s) (?:the |a |an )?([a-z ]+?)[.!]?", clause)
    if not m:
        return False
    *words, head = m.group(1).split()
    return (head in PACKAGING or head in GENERIC) and all(w in ATTRIBUTES for w in words)


def _held_only(clause: str, before: list[str]) -> bool:
    """The clause lets go of "it" or keeps hold of it, and names nothing the steps before did not ("let go of it
    above the bowl")."""
    m = _NO_STEP.match(clause)
    if not m:
        return False
    rest = clause[m.end() :].strip()
    if not rest:
        return True
    found, _why = _mentions(rest)
    said = {m.phrase for step in before for m in (_mentions(step, later=True)[0] or [])}
    return found is not None and all(x.phrase in said for x in found)


# A thing named first, then what to do with it ("the beads in the red mug - pour them into the bowl", "blue block:
# put it in the tray"): the thing, a break, and a request that says "it" or "them".
_TOPIC = re.compile(r"^\s*([^,:;\u2013\u2014]+?)\s*(?:,|:|\s-+\s|\u2013|\u2014)\s*(.*\b(?:it|them)\b.*)$")


def _topic_first(instruction: str) -> str | None:
    """The request with its "it" or "them" read as the thing named before it, when the sentence opens with a noun
    phrase alone (no verb, no goal word: "blue block - put it in the yellow tray" -> "put blue block in the yellow
    tray"); None otherwise."""
    m = _TOPIC.match(instruction.lower().replace("\u2019", "'"))
    if not m:
        return None
    topic, rest = m.group(1), m.group(2)
    tokens = _tokens(topic)
    found, _why = _mentions(topic)
    actions, goal = intent(tokens)
    rest_actions, _goal = intent(_tokens(rest))
    if not found or actions or goal or [x.role for x in found].count("thing") != 1 or not rest_actions:
        return None
    return re.sub(r"\b(?:it|them)\b", topic, rest, count=1)


def _readings(instruction: str) -> tuple[list[list[Clause]], str]:
    """The readings of the instruction as said, or of it said another way when that reads and it does not: a thing
    named first, then said as "it" (`_topic_first`); the request without the words that frame it ("i'd appreciate
    it if you put ...": rules/framing.py); a container said to end up full (rules/shapes.py)."""
    topic = _topic_first(instruction)
    if topic is not None:
        found = _readings_of(topic)
        if found[0]:
            return found
    as_said = _readings_of(instruction)
    if as_said[0]:
        return as_said
    for other in (unframed(instruction, _closed), as_moved(instruction)):
        found = _readings_of(other) if other is not None else ([], "")
        if found[0]:
            return found
    return as_said


def _readings_of(instruction: str) -> tuple[list[list[Clause]], str]:
    """Several steps ("X, then Y", "X, carry it to Y"): each read on its own, a later one's "it" the thing said
    before; the readings of the whole are every combination of the steps' readings (the planner keeps the one plan
    that grounds)."""
    steps, dropped = _steps(instruction)
    if len(steps) < 2:
        read, why = _one_step(steps[0] if steps and dropped else instruction)
        if not read and re.fullmatch(r"[2-3] things acted on", why):
            return _pairs(steps[0] if steps and dropped else instruction) or (read, why)
        return read, why
    each: list[list[list[Clause]]] = []
    for n, step in enumerate(steps):
        found, why = _one_step(step, later=n > 0)
        if not found:  # no step of its own ("..., then leave it be"): the whole as one step, as before
            whole, why_whole = _one_step(instruction)
            return whole, why_whole and f"{why_whole} (as steps: step {n + 1}: {why})"
        each.append(found)
    combos = list(itertools.product(*each))
    if len(combos) > _MAX_COMBINATIONS:
        return [], "too many readings"
    return [[replace(c, text=instruction) for r in combo for c in r] for combo in combos], ""


# Where a list of goals said without verbs breaks ("the pear in the pot and the lime in the tray").
_PAIRS = re.compile(r"\s*(?:[,;]\s*(?:and\s+|then\s+)?|\s+and\s+)")


def _pairs(instruction: str) -> tuple[list[list[Clause]], str] | None:
    """Two or three things, each with where it goes, in one sentence with no word that orders them ("the pear in
    the pot and the lime in the tray", "pear into the pot, lime into the tray"): each part read as a step of its
    own when every part reads (a later part's "the green one" is of the kind said before it); None otherwise."""
    parts = [p for p in _PAIRS.split(instruction) if p.strip()]
    if not 2 <= len(parts) <= 3:
        return None
    each: list[list[list[Clause]]] = []
    for n, part in enumerate(parts):
        found, why = _one_step(part, later=n > 0)
        if not found and why == "'one' with no noun before it" and each:
            kind = _head(re.split(r" (?:not|on|in|next to|beside|near|between) ", each[-1][0][-1].obj or "one")[0])
            found, why = _one_step(re.sub(r"\bones?\b", kind, part, count=1), later=True)
        if not found or any(c.action not in ("put", "stack", "pour") for r in found for c in r):
            return None
        each.append(found)
    combos = list(itertools.product(*each))
    if len(combos) > _MAX_COMBINATIONS:
        return None
    return [[replace(c, text=instruction) for r in combo for c in r] for combo in combos], ""


def _one_step(instruction: str, later: bool = False) -> tuple[list[list[Clause]], str]:
    read, why = _one_step_as_said(instruction, later)
    if read or why in ("negation", "question"):
        return read, why
    return _moved_by_frame(instruction, later) or (read, why)


def _moved_by_frame(instruction: str, later: bool) -> tuple[list[list[Clause]], str] | None:
    """A verb the planner lacks that opens the request, in a frame only a move fits ("dunk the cube into the
    bowl": rules/frames.py): the request read without it, as a put, when what is left is one thing and one place
    it goes to; None otherwise."""
    tokens = _tokens(instruction)
    n = leading_verb(tokens)
    if n is None or _verb_spans(tokens) or intent(tokens)[0]:
        return None
    rest = " ".join(tokens[:n] + tokens[n + 1 :])
    found, _why = _mentions(rest, later)
    if not found:
        return None
    rest_tokens = _tokens(rest)
    roles = sorted(m.role for m in found)
    dests = [m for m in found if m.role == "dest"]
    if roles not in (["dest", "thing"], ["dest", "source", "thing"]) or not goes_to(rest_tokens, dests[0].start):
        return None
    read, _why = _one_step_as_said(f"put {rest}", later)
    return (read, "") if read else None


def _one_step_as_said(instruction: str, later: bool = False) -> tuple[list[list[Clause]], str]:
    found, why = _mentions(instruction, later)
    if not found:
        return [], why or "no mention"
    tokens = _tokens(instruction)
    found = [_sided(m, tokens) for m in found]
    actions, goal = intent(tokens)
    # an arrow says where it goes; a sentence of a thing and where it is, and nothing else, states the goal
    goal = goal or bool(re.search(r"-+>|=>|\u2192", instruction))
    roles = sorted(m.role for m in found)
    # ... or of a thing and where it is and where it goes, in either order: the scene tells which is which
    # (or where it comes from and where it goes: "beads out of the mug and in the bowl")
    goal = goal or (
        not actions and roles in (["dest", "thing"], ["dest", "dest", "thing"], ["dest", "source", "thing"])
    )
    things = [m for m in found if m.role == "thing"]
    if len(things) == 2 == len(found) and not actions and _listed_into(things, tokens):
        # "ketchup, basket": a thing and, after a comma, the container it goes in (a terse goal)
        found = [things[0], replace(things[1], role="dest", relation="in")]
        things, goal = things[:1], True
    if len(things) != 1:
        return [], f"{len(things)} things acted on"
    if any(m.role == "tool" for m in found):
        return [], "a tool"
    thing = things[0]
    obj = _qualified(thing.phrase, tokens)
    if actions & {"open", "close", "turn_on", "turn_off"}:
        if len(actions) == 1 and len(found) == 1:
            return [[Clause(next(iter(actions)), obj=obj, text=instruction)]], ""
        return [], "a fixture's action with more"
    if not (actions <= {"put", "stack", "pick", "pour", "push"}):
        return [], f"actions {sorted(actions)}"
    if not (actions or goal):
        return [], "no verb and no goal"
    dests = [m for m in found if m.role == "dest"]
    sources = [m for m in found if m.role == "source"]
    near = [m for m in found if m.role == "near"]
    if _head(thing.phrase) in CONTENTS or "pour" in actions:  # "the beads out of the mug and into the bowl"
        # "pour the beads in the red mug into the bowl": what they are in, said right after them, is the source
        held_in = [d for d in dests if d.relation == "in" and d.start == thing.end and len(dests) == 2]
        sources, dests = sources + held_in, [d for d in dests if d not in held_in]
        if len(dests) == 1 and len(sources) <= 1 and not near and actions <= {"pour", "put"}:
            source = sources[0].phrase if sources else obj
            return [[Clause("pour", obj=obj, target=dests[0].phrase, source=source, text=instruction)]], ""
        return [], "contents without one destination"
    if "push" in actions:
        # pushed into a flat area ("shove the cube into the green patch"): the one place it goes
        if len(dests) == 1 and not sources and not near and actions <= {"push", "put"} and _region(dests[0].phrase):
            return [[Clause("push", obj=obj, target=dests[0].phrase, relation="in", text=instruction)]], ""
        return [], "push"
    out: list[list[Clause]] = []
    for d in dests:
        where = [m for m in found if m is not d and m.role in ("dest", "source", "near")]
        located = obj
        for m in sorted(where, key=lambda m: m.start):
            rel = m.relation or "on"
            located = f"{located} {rel} {m.phrase}"
        if len(where) > 1:
            continue  # located by two things: the rule parser's to read
        relation = d.relation or ("in" if _head(d.phrase) in CONTAINERS else "on")
        action = "stack" if "stack" in actions else "put"
        out.append([Clause(action, obj=located, target=d.phrase, relation=relation, text=instruction)])
    if not dests and not sources and not near and actions == {"pick"}:
        out.append([Clause("pick", obj=obj, text=instruction)])
    if not out:
        return [], "no destination" if not dests else "located by two things"
    return out, ""


def phrases(instruction: str) -> list[str]:
    """What perception should look for so that each reading can be grounded (observe.py)."""
    from .afford import phrases as afforded_phrases  # (afford.py reads with this module's words)

    out: dict[str, None] = {}
    for reading in readings(instruction):
        for c in reading:
            for p in (c.obj, c.target, c.source):
                if p and not is_pronoun(p):
                    out.setdefault(p, None)
    # the mentions the scene-afforded reading grounds (the planner's last fallback, rules/afford.py)
    for p in afforded_phrases(instruction):
        out.setdefault(p, None)
    # each step said on its own (rules/stepwise.py, the planner's fallback for instructions of several steps): what
    # observe looks for in it (a step has no steps of its own, so this recursion ends there)
    from ..observe import phrases_for  # observe reads with this package; imported here, when it is loaded

    for text in steps(instruction):
        for p in phrases_for(text):
            out.setdefault(p, None)
    return list(out)


def describe(reading: list[Clause]) -> str:
    out = []
    for c in reading:
        parts = [c.action, f"thing={c.obj}"]
        parts += [f"{c.relation or 'to'}={c.target}"] if c.target else []
        parts += [f"from={c.source}"] if c.source else []
        out.append(" ".join(parts))
    return "; then ".join(out)


def unused_mentions(instruction: str, clauses: list[Clause]) -> list[str]:
    """Things the sentence names as the thing acted on or a destination that no clause of the rule parse holds
    ("the bowl needs to be up on top of the cabinet" read as a lift of the bowl: the cabinet is unused)."""
    found = mentions(instruction)
    if not found:
        return []
    said = {
        w for c in clauses for p in (c.obj, c.target, c.tool, c.source) if p for w in re.findall(r"[a-z]+", p.lower())
    }
    out = []
    for m in found:
        heads = [w for w in re.split(r"\s+not\s+", m.phrase)[0].split() if not _closed(w)][
            -1:
        ]  # "bowl right": the bowl, "right" says where
        if m.role in ("thing", "dest") and heads and not (heads[0] in said or singular(heads[0]) in said):
            out.append(m.phrase)
    return out
