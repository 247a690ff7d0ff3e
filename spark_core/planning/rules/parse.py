"""Instruction -> clauses (action, object phrase, target phrase, tool, source, direction), with pronouns
resolved across clauses and sentences. Wording is first brought to imperative clauses (rewrite.py); each clause's
action comes from its verb, its destination from the last destination preposition (what comes before it, including
where the object is now, locates the object)."""

from __future__ import annotations

import re
from dataclasses import dataclass, field, replace

from ...perception.colors import BASE_COLOURS
from ...perception.qualifiers import split_relation
from ...perception.variants import SIZES
from .lexicon import (
    CONTAINERS,
    CONTENTS,
    CONTENTS_SAID,
    DIRECTIONS,
    FROM,
    IN,
    ON,
    PARTICLE_VERBS,
    PRONOUNS,
    TABLE,
    VERBS,
    WITH,
)
from .phrases import BESIDE, noun_phrase, object_phrase
from .qualify import EXTREMES
from .rewrite import bare_goal, goal_to_action, imperatives
from .things import is_verb, names_a_thing

_ATTRIBUTE_WORDS = frozenset([*BASE_COLOURS, *SIZES])


class ParseError(ValueError):
    """The instruction could not be understood; the message says what was and what was not."""


@dataclass(frozen=True)
class Clause:
    action: str  # a key of lexicon.VERBS, or "mention" (an object introduced for a later pronoun)
    obj: str | None = None  # object phrase (determiners stripped), or a pronoun
    target: str | None = None  # where it goes / what is poured into / what is scrubbed
    relation: str | None = None  # on | in | near (for put/stack/push)
    tool: str | None = None  # scrub with
    source: str | None = None  # pour from
    direction: str | None = None  # forward | backward | left | right
    distance_m: float | None = None
    together: bool = False  # one of the handles a two-armed lift grips at once ("... with both arms")
    arm: str | None = None  # the arm that picks it: right | left | one (the nearer)
    to_arm: str | None = None  # the arm it is handed to: right | left | other
    text: str = field(default="", compare=False)
    # a remark before the request (no verb read in it) that names a thing no step after it uses: a step not read,
    # which the planner refuses (never drops) once every thing named is found
    unread: bool = field(default=False, compare=False)


# Destination prepositions, longest first; the last one in a clause starts its destination.
_DEST = re.compile(
    r"(?<!next )(?<!close )\b(to the front of|in front of|to the top of|on top of|onto|on to|into|inside of|inside|"
    r"within|atop|over|in|on|to)\b"
)
_RELATION_OF = {"onto": "on", "on to": "on", "on top of": "on", "atop": "on", "over": "on", "on": "on"}
_RELATIONS = (
    "between",
    "next to",
    "beside",
    "near",
    "by",
    "on top of",
    "on",
    "in",
    "inside",
    "under",
    "below",
    "behind",
)


def _split_on(phrase: str, preps: tuple[str, ...]) -> tuple[str, str] | None:
    for p in sorted(preps, key=len, reverse=True):
        m = re.search(rf"(^|\s){re.escape(p)}(\s|$)", phrase)
        if m:
            return phrase[: m.start()].strip(), phrase[m.end() :].strip()
    return None


def _direction(phrase: str) -> tuple[str | None, str]:
    for d, forms in DIRECTIONS.items():
        for f in sorted(forms, key=len, reverse=True):
            m = re.search(rf"(^|\s){re.escape(f)}(\s|$)", phrase)
            if m:
                return d, (phrase[: m.start()] + " " + phrase[m.end() :]).strip()
    return None, phrase


def _distance(phrase: str) -> tuple[float | None, str]:
    m = re.search(r"(\d+(?:\.\d+)?)\s*(cm|centimeters|centimetres|mm|m|meters|metres)\b", phrase)
    if not m:
        return None, phrase
    value = float(m.group(1)) * {"cm": 0.01, "centimeters": 0.01, "centimetres": 0.01, "mm": 0.001}.get(m.group(2), 1.0)
    return value, (phrase[: m.start()] + phrase[m.end() :]).replace(" by ", " ").strip()


def _match_verb(clause: str) -> tuple[str, str] | None:
    m = re.fullmatch(r"(?:turn|switch) (.+?) (?:to )?(on|off)", clause)  # "turn the stove on", "... knob to on"
    if m:
        return ("turn_on" if m.group(2) == "on" else "turn_off"), m.group(1)
    m = re.fullmatch(r"(?:pull|slide|draw|haul|yank|swing|ease) (.+) (?:open|out)", clause)
    if m:
        return "open", m.group(1)
    m = re.fullmatch(r"(?:push|slide|pull|swing|ease) (.+) (?:closed|shut)|(?:push|slide) in (.*drawer.*)", clause)
    # "slide it back in" said of a drawer named before: closing it
    m = m or re.fullmatch(r"(?:push|slide) ()(it|that one|this one)(?: back)? in", clause)
    m = m or re.fullmatch(r"(?:push|slide) ()(.*drawer.*?)(?: back)? in", clause)
    if m:  # "push the drawer in": a drawer pushed in is a drawer closed
        return "close", m.group(1) or m.group(2)
    m = re.fullmatch(r"there (?:is|are) (.+)", clause)
    if m:
        return "mention", m.group(1)
    best = None
    for action, forms in VERBS.items():
        for f in forms:
            if (clause == f or clause.startswith(f + " ")) and (best is None or len(f) > len(best[2])):
                best = (action, clause[len(f) :].strip(), f)
    return (best[0], best[1]) if best else None


_CARRIED_TO = r"(?:into|onto|on top of|in|on|inside)(?: (?:the|a|an))?"


def _pairs(part: str) -> list[str]:
    """ "red into the green tray and blue into the yellow tray": a bare second thing and its place after a first
    pair with its place, two carries (the split on "and the ..." misses it for want of an article)."""
    pieces = part.split(" and ")
    out = [pieces[0]]
    for piece in pieces[1:]:
        if re.search(rf"\b{_CARRIED_TO} (?:\w+ ){{0,2}}\w+$", out[-1]) and re.match(
            rf"(?:\w+ ){{0,2}}\w+ {_CARRIED_TO}\b", piece
        ):
            out.append(piece)
        else:
            out[-1] = f"{out[-1]} and {piece}"
    return out


def split_clauses(text: str) -> list[str]:
    verbs = "|".join(re.escape(f) for forms in VERBS.values() for f in forms)
    parts = re.split(
        r"\s*,\s*(?:and\s+)?(?:then\s+)?|\s+(?:and\s+)?then\s+|\s+and\s+(?=(?:(?:"
        + _HEDGES
        + r") )?(?:"
        + verbs
        + r"|turn|switch|use)\b)|\s+(?:and\s+)?after that\s+|\s+afterwards\s+|\s+before\s+",
        text,
    )
    out: list[str] = []
    # a conjunction left at a part's end by a split after it ("slide the drawer out and afterwards ...")
    parts = [re.sub(r"\s+(?:and|then|and then)$", "", p.strip()) if p else p for p in parts]
    for part in (p.strip() for p in parts if p and p.strip()):
        if part in ("after that", "afterwards", "then", "and"):
            continue
        # "put A in B and C in D": a second object/target pair after "and" ("between the plate and the
        # ramekin" is one phrase)
        if " between " in f" {part} ":
            out.append(part)
        else:
            out += [q for p in re.split(r"\s+and\s+(?=(?:the|a|an)\s)", part) if p.strip() for q in _pairs(p)]
    # "... and balance it on the blue one": a verb the lexicon knows, outside the planner's list, starts a clause
    split: list[str] = []
    for part in out:
        pieces = re.split(r"\s+and\s+(?=\w+ (?:it|them|the|a|an)\b)", part)
        head = pieces[0]
        for piece in pieces[1:]:
            if is_verb(piece.split(" ", 1)[0]):
                split.append(head)
                head = piece
            else:
                head = f"{head} and {piece}"
        split.append(head)
    return split


def parse_instruction(instruction: str) -> list[Clause]:
    texts = imperatives(instruction)
    if not texts:
        raise ParseError("the instruction is empty")
    clauses: list[Clause] = []
    remarks: list[Clause] = []  # parts read as a remark before the request (no verb read in them)
    previous: str | None = None
    parts = [p for t in texts for p in split_clauses(t)]
    for i, part in enumerate(parts):
        said = re.fullmatch(r"(?:the |a |an )?(\w+) one", part)
        if said and previous == "mention" and said.group(1) in _ATTRIBUTE_WORDS and clauses[-1].obj:
            # "there is a bowl in the drawer, black one": what the thing just named looks like
            clauses[-1] = replace(clauses[-1], obj=f"{said.group(1)} {clauses[-1].obj}")
            continue
        # "use the sponge (lying to the right of the plate) to scrub the plate": "to" before a verb, not a place
        part = re.sub(
            r"^use (.+?) to (?!(?:the|a|an|its|my|your|his|her|their|our)\b)(\w+) (.+)$", r"\2 \3 with \1", part
        )
        part = re.sub(
            r"^slide (.+) (?:over(?! to\b)|onto|on to|on top of) ", r"put \1 on ", part
        )  # slid on top: a carry
        verb = _match_verb(part)
        hedged = re.match(rf"(?:{_HEDGES}) (?=\w)", part)
        if verb is None and hedged and _match_verb(part[hedged.end() :]):
            part = part[hedged.end() :]  # "- just put the butter in the basket": the hedge says nothing of what
            verb = _match_verb(part)
        if verb is None:
            goal = goal_to_action(part)
            verb = _match_verb(goal) if goal else None
        verbless_carry = bool(
            re.match(r"(?:the|a|an) \w.* (?:into|onto|on top of|inside|in|on) (?:the|a|an) \w", part)
            # without an article only with a preposition that can only say where it goes ("red block onto the plate")
            or re.match(r"[a-z][\w ]* (?:into|onto|on to) (?:the|a|an) \w", part)
            # "red block to the green tray": a noun phrase (not a verb: "fly to the moon") and a destination last
            # (a possessive in it: "the wooden cabinet's black bowl over to the plate")
            or re.fullmatch(
                r"(?:the |a |an )(?!(?:it|that|there|what|here)'s\b)[a-z][\w ]*(?:'s [\w ]+)?(?<!next)(?<!close) to "
                r"(?:the|a|an) \w+(?: \w+)?",
                part,
            )
            or re.fullmatch(r"[a-z][\w ]*(?<!next)(?<!close) to (?:the|a|an) \w+(?: \w+)?", part)
            and not is_verb(part.split()[0])
            # after a thing named on its own: "blue block, then red block on it"
            or previous == "mention"
            and re.fullmatch(r"[a-z][\w ]* (?:on top of|onto|into|on|in|inside) (?:it|them)", part)
        )
        if (  # "the bowl sitting on the box, put it on the plate": where it sits names it; the goal comes after
            previous in (None, "mention")
            and _topic(part, parts[i + 1 :])
            and re.search(
                rf"\b(?:{_WHERE_PARTICIPLES})(?: up| down)? (?:on|in|at|by|near|next to|beside|between)\b", part
            )
        ):
            verb = ("mention", part)
        named = re.fullmatch(r"(?:the|a|an) ((?:\w+ ){0,2}\w+)", part)
        if verb is None and previous == "mention" and named and names_a_thing(named.group(1)):
            verb = ("mention", part)  # "there's a green cube and a red cube": one more thing named
        if verb is None and previous in (None, "mention") and _topic(part, parts[i + 1 :]):
            verb = ("mention", part)  # "the bowl on the stove, move it to the plate": named first, then acted on
        if verb is None and previous in (None, "mention") and verbless_carry:
            verb = ("put", part)  # "first the red block into the green tray", "I want the cup on the saucer"
        if verb is None and (
            previous in (None, "mention")
            # "top drawer open, cream cheese inside it": a goal said after a fixture's state is a carry, not the
            # same state again
            or previous in _FIXTURE_ACTIONS
            and re.search(r"\b(?:in|inside|into|on|onto|on top of) (?:it|the|a|an)\b", part)
        ):
            goal = bare_goal(part)  # "red block in the cabinet drawer": no verb, a thing and a place
            verb = _match_verb(goal) if goal else None
        if verb is None:
            verb = _unknown_verb(part)  # "balance it on the blue one": a verb the list lacks, with a destination
        if verb is None and previous is None and i < len(parts) - 1:
            # a remark before the request ("hey", "when you get a sec", "someone left the drawer open"): no
            # step, but a thing it names is there for a pronoun after it (and must be in the scene: mentions.py)
            named = re.search(r"\b(?:the|a|an) ((?:\w+ ){0,2}?\w+)(?: (?:open|closed|shut|on|off|there|here))?$", part)
            if named and names_a_thing(named.group(1)):
                clauses.append(Clause("mention", obj=object_phrase(named.group(1)), text=part))
                remarks.append(clauses[-1])
                previous = "mention"
            continue
        if verb is None:
            if previous is None or previous == "mention":
                known = ", ".join(sorted({f for forms in VERBS.values() for f in forms[:2]}))
                raise ParseError(f"no action I know in {part!r}; I understand verbs such as {known}")
            verb = (previous, part)  # ellipsis: "..., then the red block on the green block"
            gapped = True
        else:
            gapped = False
        action, rest = verb
        rest = _demonstrative(rest, clauses)
        clause = _clause(
            action, rest, part, clauses[-1].obj if clauses else None, clauses[-1].target if clauses else None
        )
        clause = _resolve(clause, clauses)
        clause = _elided_object(clause, clauses)
        # "grasp the red block, lower onto the blue block": a carry with no object carries what was just taken
        if clause.action in ("put", "stack") and clause.obj is None and clause.target and _took(clauses):
            clause = replace(clause, obj=clauses[-1].obj)
        if gapped and clause.target and clauses and _shares_destination(clauses[-1], clause):
            # "put the fork and the knife in the tray": coordinated objects share the one destination named last
            clauses[-1] = replace(clauses[-1], target=clause.target, relation=clause.relation)
        previous = clause.action
        clauses.append(clause)
    clauses = [_remaining(c, clauses[:i]) for i, c in enumerate(clauses)]
    clauses = _said_once(_open_before_filling(_grip_then_act(_named_before(clauses))))
    if all(c.action == "mention" for c in clauses):
        raise ParseError(f"{instruction.strip()!r} names {', '.join(c.obj or '?' for c in clauses)} but no action")
    for remark in remarks:
        at = next((i for i, c in enumerate(clauses) if c.action == "mention" and c.text == remark.text), None)
        if at is not None and not _remark_used(clauses[at], clauses[at + 1 :]):
            clauses[at] = replace(clauses[at], unread=True)  # "into the green bin with the lime. the pear ..."
    return clauses


def _named_before(clauses: list[Clause]) -> list[Clause]:
    """ "open the top drawer and put the cream cheese in the drawer": a destination said by its kind alone is the
    one of that kind an earlier step worked or carried ("the drawer": the top drawer just opened), not any of them."""
    out: list[Clause] = []
    for c in clauses:
        if c.target and re.fullmatch(r"[a-z]+", c.target) and not is_pronoun(c.target):
            fuller = [
                p.obj for p in out if p.action != "mention" and p.obj and " " in p.obj and _head_word(p.obj) == c.target
            ]
            if len(set(fuller)) == 1:
                c = replace(c, target=fuller[0])
        out.append(c)
    return out


def _head_word(phrase: str) -> str:
    """The noun a phrase names its thing by, before where it is ("bowl next to plate" -> "bowl")."""
    words = split_relation(phrase)[0].split()
    return words[-1] if words else ""


def _said_once(clauses: list[Clause]) -> list[Clause]:
    """A fixture worked twice in a row is one step said twice ("the drawer should be open, can you open it?")."""
    out: list[Clause] = []
    for c in clauses:
        prev = out[-1] if out else None
        if prev and c.action in _FIXTURE_ACTIONS and (c.action, c.obj) == (prev.action, prev.obj):
            continue
        out.append(c)
    return out


# Words said before a part's verb that only soften or time it ("just put ...", "simply drop ...", "now open ...").
_HEDGES = "just|simply|only|merely|now|also|instead|rather|kindly|quickly|gently|carefully|slowly|so|then"
# A remark that only says the robot goes near a thing ("go over to the cabinet, take hold of the handle ..."): the
# step after it reaches there anyway.
_APPROACH = re.compile(r"^(?:go|walk|head|come|move|get)(?: over| up| back)? (?:to|towards?)\b")


def _remark_used(remark: Clause, later: list[Clause]) -> bool:
    """A remark before the request is no step but must serve one: a thing it names is what a later step acts on, or
    is said again or referred back to by a pronoun after it ("someone left the drawer open, close it"), or it only
    says to go near a thing."""
    if _APPROACH.match(remark.text):
        return True
    said = f" {remark.obj} "
    for c in later:
        phrases = [p for p in (c.obj, c.target, c.source, c.tool) if p]
        if any(is_pronoun(p) or said in f" {p} " for p in phrases) or said in f" {c.text} ":
            return True
    return False


def _took(before: list[Clause]) -> bool:
    """The clause before took hold of a thing it names."""
    return bool(before) and before[-1].action == "pick" and before[-1].obj is not None


_GRIPPED_PARTS = ("handle", "knob", "dial", "grip", "pull")


def _grip_then_act(clauses: list[Clause]) -> list[Clause]:
    """ "grab the drawer handle and pull the drawer open": taking hold of a part is how the action after it is
    done (the open grips the handle itself), not a step of its own."""
    return [
        c
        for i, c in enumerate(clauses)
        if not (
            c.action == "pick"
            and c.obj
            and c.obj.split()[-1] in _GRIPPED_PARTS
            and i + 1 < len(clauses)
            and clauses[i + 1].action in ("open", "close", "turn_on", "turn_off")
        )
    ]


def _open_before_filling(clauses: list[Clause]) -> list[Clause]:
    """ "stow the block in the drawer, you will need to open the drawer first": an open said after the carry into
    the same drawer, with no carry after it, comes first."""
    out = list(clauses)
    for i, c in enumerate(clauses):
        if c.action != "put" or c.relation != "in" or not c.target:
            continue
        for j in range(i + 1, len(clauses)):
            later = clauses[j]
            if later.action == "open" and later.obj == c.target and not any(x.action == "put" for x in clauses[j:]):
                out.remove(later)
                out.insert(out.index(c), later)
                return out
    return out


def _demonstrative(rest: str, before: list[Clause]) -> str:
    """ "there is a black bowl in the top drawer; that bowl goes on the plate": "that"/"this"/"the same" before the
    kind just named points back to that very thing, as "it" does."""
    prev = next((b.obj for b in reversed(before) if b.obj and not is_pronoun(b.obj)), None)
    if not prev:
        return rest
    kind = split_relation(prev)[0].split()[-1]
    return re.sub(rf"^(?:that|this|the same) {re.escape(kind)}s?\b", "it", rest)


def _elided_object(c: Clause, before: list[Clause]) -> Clause:
    """ "..., the red one belongs in the green tray": an object said by its colour or size alone ("one" dropped)
    is one of the kind named before ("red block")."""
    if not c.obj or " " in c.obj or c.obj not in _ATTRIBUTE_WORDS:
        return c
    # the head noun before a negation or a relation ('block not blue' is a block)
    kind = next((head_noun(b.obj) for b in reversed(before) if b.obj and not is_pronoun(b.obj)), None)
    if not kind or kind in _ATTRIBUTE_WORDS:  # "red in the tray and blue in ...": no kind was named
        return c
    return replace(c, obj=f"{c.obj} {kind}")


def _unknown_verb(part: str) -> tuple[str, str] | None:
    """A clause that starts with a verb the lexicon knows but the planner's list lacks, and says where its object
    goes ("balance it on the blue one", "wedge the box into the basket"): a carry."""
    first, _, rest = part.partition(" ")
    if not rest or not is_verb(first) or not re.match(r"(?:it|them|the|a|an|this|that|these|those)\b", rest):
        return None
    dest = _destination(rest)
    return ("put", rest) if dest and dest[2] and dest[0] else None


def _remaining(c: Clause, before: list[Clause]) -> Clause:
    """ "then the remaining block on top of the green one": the one of the kind not named yet, i.e. not any of the
    kind's attributes said before ("block not green blue": perception keeps the blocks those words contradict).
    "The other <kind>" / "the other one" is the complement of the one of that kind picked out just before, in this
    clause or an earlier one, whatever picked it out (`_complement`: an attribute, a side or extreme, a relation to
    another thing, or a negation of one of those)."""
    updates: dict = {}
    for name in ("obj", "target"):
        phrase = getattr(c, name)
        m = re.fullmatch(r"(?:remaining|leftover|last remaining|spare) (\w+)", phrase or "")
        if not m and phrase:
            # latest first, a thing said in the same role first ("..., blue block into the other one": the other
            # destination), then the clause's own object ("put the red cube on the other one")
            same = [getattr(b, name) for b in reversed(before)]
            rest = [c.obj if name == "target" else None] + [
                b.obj if name == "target" else b.target for b in before[::-1]
            ]
            said = [p for p in [*same, *rest] if p and not is_pronoun(p)]
            other = _other_of(phrase, c.text, said)
            if other:
                updates[name] = other
            continue
        if not m:
            continue
        noun = m.groups()[-1]
        said = [
            w
            for b in before
            for p in (b.obj, b.target)
            if p and p.split()[-1] == noun
            for w in p.split()[:-1]
            if w not in ("not",)
        ]
        if said:
            updates[name] = f"{noun} not {' '.join(dict.fromkeys(said))}"
    return replace(c, **updates) if updates else c


def head_noun(phrase: str) -> str:
    """The head noun of a phrase perception reads: before a negation or a relation ("block not blue" -> block)."""
    head = re.split(r"\s+not\s+", phrase)[0]
    head = split_relation(head)[0] if split_relation(head)[1] else head
    return head.split()[-1] if head.split() else ""


def _other_of(phrase: str, text: str, said: list[str]) -> str | None:
    """ "the other <kind>" / "the other one" in the clause's words: the complement of the latest phrase of that kind
    said before it (`said`, latest first); None when the words say no "other" or nothing of the kind was said."""
    if phrase in ("one", "ones"):
        if not re.search(r"\bthe other ones?\b", text) or not said:
            return None
        ref = said[0]
    else:
        kind = phrase.split()[-1]
        # "the other (black) bowl": describing words only between, never another phrase ("the other block in the
        # yellow tray" says no other tray)
        between = r"(?:(?!(?:in|on|into|onto|inside|to|at|by|with|from|of|the|a|an|and|then|not)\b)\w+ ){0,2}"
        if not re.search(rf"\bthe other {between}{re.escape(kind)}s?\b", text):
            return None
        found = next((p for p in said if (head_noun(p) == kind or _ELIDED_HEAD.match(p)) and p != phrase), None)
        if found is None:
            return None
        # "not the one on the stove: the other black bowl": the one said by where it is was of this kind
        ref = f"{kind} {found}" if _ELIDED_HEAD.match(found) else found
    return _complement(ref, None if phrase in ("one", "ones") else phrase)


# A phrase whose noun went with "one" ("the one on the stove" -> "on stove"): the thing said only by where it is.
_ELIDED_HEAD = re.compile(r"(?:on|in|inside|on top of|next_to|next to|beside|near|by|under|between) ")


def _complement(ref: str, phrase: str | None) -> str | None:
    """The phrase for "the other" of the kind `ref` picks out, in perception's forms: "red block" -> "block not red";
    "block not blue" -> "blue block"; "black bowl on stove" -> "black bowl not on stove"; "bowl not on stove" ->
    "bowl on stove"; "leftmost black bowl" (with "black bowl" said as the other) -> "black bowl not leftmost"."""
    core, _, ruled = ref.partition(" not ")
    if ruled:
        head, relation, _anchors = split_relation(f"{core} {ruled}")
        return f"{core} {ruled}" if relation else f"{ruled} {core}"
    head, relation, anchors = split_relation(ref)
    if relation:
        return f"{head} not {relation} {' and '.join(anchors)}"
    words = ref.split()
    base = (phrase or words[-1]).split()
    mods = [w for w in words[:-1] if w not in base]
    return f"{' '.join(base)} not {' '.join(mods)}" if mods else None


def _topic(part: str, later: list[str]) -> bool:
    """A noun phrase said on its own before a clause that refers back to it ("the black bowl on the stove, move
    that one onto the plate", "the ketchup? put it in the basket"): it names the thing the pronoun stands for."""
    if not later:
        return False
    bare = re.fullmatch(r"[a-z]+(?: [a-z]+){0,2}", part)  # without an article: a short bare noun phrase only
    # ... or one located by a relative clause ("black bowl that is on the cooktop, plate it")
    bare = bare or re.fullmatch(
        r"[a-z]+(?: [a-z]+){0,2} (?:that|which) (?:is|are) (?:on|in|inside|at|by|near|next to|beside|under|between) "
        r"(?:the|a|an) [a-z ]+",
        part,
    )
    # ... or by where it is alone, when a request acting on it comes next ("bowl on the stove, put it on the plate",
    # "..., transfer to the plate"; "red block in the bowl, then put the blue block on it" is two carries)
    acted = _match_verb(later[0])
    on_it = acted is not None and bool(
        re.match(r"(?:(?:it|them|that one|this one)\b|(?:to|into|onto|on|in|inside)\s)", acted[1])
    )
    if bare is None and on_it:
        bare = re.fullmatch(
            r"(?!(?:look|see|check|watch|find|spot|notice|go|come)\b)[a-z]+(?: [a-z]+){0,2} "
            r"(?:on|in|inside|by|near|next to|beside|under|between) (?:the|a|an) [a-z ]+",
            part,
        )
    if not re.match(r"(?:the|a|an|this|that|these|those) \w", part) and not bare:
        return False
    if re.search(r"\b(?:onto|into|on to)\b", part):  # "the red block onto the plate, then ...": a carry
        return False
    # "..., put that on the plate": a bare demonstrative before a preposition points back as "it" does
    back = r"\b(?:it|them|that one|this one|(?:that|this)(?= (?:on|onto|in|into|to|over|inside)\b))\b"
    return re.search(back, later[0]) is not None


def _shares_destination(first: Clause, second: Clause) -> bool:
    """A carry that names no destination, then an elided carry of the same kind that does ("put A and B in C")."""
    return first.action == second.action and first.action in ("put", "stack", "sort") and first.target is None


def _anchor(phrase: str | None) -> str | None:
    """The object a phrase locates its object by ("bowl next to plate" -> "plate")."""
    if not phrase:
        return None
    m = re.search(r"\b(?:" + "|".join(_RELATIONS) + r")\s+(.+)$", phrase)
    return m.group(1).split(" and ")[0] if m else None


def _resolve(c: Clause, before: list[Clause]) -> Clause:
    """Pronouns across clauses: "it" as the object is the previous clause's object; as a destination, the most
    recent thing mentioned that is not the object itself (the previous object, its destination, or what it was
    located by); as a tool, the previous object. A push of something just picked up is a carry."""
    if not before:
        anchor = _anchor(c.obj)
        if is_pronoun(c.target) and anchor and not is_pronoun(c.obj):
            return replace(c, target=anchor)  # "put the bowl nearer the plate onto it": onto the plate
        return c
    prev = before[-1]
    updates: dict = {}
    obj = c.obj
    # "take it out of the drawer": where "it" is only restates where the thing named before is
    if obj and re.fullmatch(r"(?:it|them) (?:in|on|from|inside|at|on top of) .+", obj):
        obj = obj.split(" ", 1)[0]
    if obj and prev.obj and re.match(r"(?:on|in|inside|on top of|next_to|next to|beside|near|by|under|between) ", obj):
        # "don't take the bowl from the cabinet. take the one on the stove": "one" is of the kind just named
        kind = split_relation(prev.obj)[0].split()
        if kind and names_a_thing(kind[-1]):
            obj = updates["obj"] = f"{kind[-1]} {obj}"
    elif (
        obj in _BARE_QUALIFIERS
        and ("mention" in (prev.action, c.action) or {prev.action, c.action} <= {"put", "stack"})
        and prev.obj
        and not is_pronoun(prev.obj)
    ):
        # "leave the black bowl in the back alone, put the front one on the plate": "one" is of the kind just named
        # (only after a thing named or for one named, not a step after a step: "open one of the drawers - ..., the
        # bottom one" says which)
        # (and in a stack said step by step: "stack the closest block on the blue one, then the rightmost one on top")
        kind = [w for w in split_relation(prev.obj)[0].split() if w not in _BARE_QUALIFIERS]
        if kind and names_a_thing(kind[-1]):
            obj = updates["obj"] = f"{obj} {' '.join(kind)}"
    if is_pronoun(obj):
        obj = prev.obj
        if c.action in ("open", "close"):  # "put the block in the drawer, you will have to open it": the drawer
            obj = next((p for p in (prev.obj, prev.target) if p and _OPENS.search(p)), obj)
        elif c.action in ("turn_on", "turn_off"):  # "put the pot on the stove and turn it on": the stove
            obj = next((p for p in (prev.obj, prev.target) if p and _SWITCHED.search(p)), obj)
        elif prev.action in _FIXTURE_ACTIONS and c.action in ("put", "stack", "pour", "push", "pick"):
            # "pick up the block, open the drawer and put it inside": a fixture just opened or switched is not what
            # is carried; the latest thing named before it that is neither a fixture worked nor the destination
            fixtures = {b.obj for b in before if b.action in _FIXTURE_ACTIONS}
            obj = next(
                (
                    b.obj
                    for b in reversed(before)
                    if b.obj and not is_pronoun(b.obj) and b.obj not in fixtures and b.obj != c.target
                ),
                obj,
            )
        updates["obj"] = obj
        if c.action == "push" and prev.action == "pick":
            updates["action"] = "put"
            if c.relation is None and c.target:
                updates["relation"] = "on"
    if is_pronoun(c.target) or c.target in ("that", "this"):  # "... then the red block on top of that"
        # (the clause before only picked the thing up: a clause before it named the place, "grab the green block and
        # put it on the blue one, then take the red one and put it on top of that")
        # ("that" points at the thing said last, the thing's own anchor: "..., the blue one beside the yellow tray
        # goes in that"; "it" at the thing talked about: "plate on the stove: put the bowl nearer the cabinet on it")
        own = [] if is_pronoun(c.obj) else [_anchor(c.obj)]
        said = [p for b in reversed(before) for p in (b.obj, b.target, _anchor(b.obj))]
        pointed = c.target in ("that", "this") or re.search(r"\b(?:that|this)(?: one)?\W*$", c.text or "")
        cands = own + said if pointed else said + own
        for cand in cands:
            if cand and cand != obj and not is_pronoun(cand):
                updates["target"] = cand
                break
    if is_pronoun(c.tool):
        updates["tool"] = prev.obj
    if is_pronoun(c.source):  # "pick up the mug and pour its beads into the bowl": poured from the mug
        updates["source"] = prev.obj
    if c.action == "pour" and is_pronoun(c.obj) and prev.obj and (c.source is None or is_pronoun(c.source)):
        # "the beads in the red mug: pour them into the bowl": poured from what holds them
        updates["source"] = _holder(prev.obj) or updates.get("source", c.source)
    return replace(c, **updates) if updates else c


# What is left of "the front one" once "one" is read: a qualifier perception reads, no kind of thing.
_BARE_QUALIFIERS = frozenset([*EXTREMES.values(), "middle"])
_WHERE_PARTICIPLES = "sitting|resting|standing|lying|perched|located|parked|kept|stacked|seated|sat|placed"
# What is switched on and off: "turn it on" after a carry onto one of these is switching it.
_SWITCHED = re.compile(r"\b(?:stove|burner|hob|cooktop|cooker|oven|lamp|light|tap|faucet|knob|dial)\b")
_FIXTURE_ACTIONS = ("open", "close", "turn_on", "turn_off")
# Things a robot opens and closes: "open it" after a carry into one of these is opening it.
_OPENS = re.compile(r"\b(?:drawer|cabinet|door|lid|box|microwave|oven|fridge|cupboard)\b")
# A preposition after one of these says where a thing is, not where it goes ("the plate that sits on the box").
_LOCATIVE_BEFORE = re.compile(
    r"\b(?:(?:that|which) (?:is|are)|(?:that|which) (?:sits?|rests?|stands?|lies|lie)|is|are|sitting|resting|"
    r"standing|lying|located|placed|found|kept|stacked|perched|parked|waiting|positioned|stored|sat|left|already)"
    r"(?: (?:up|down|over|back|right))?\s*$"
)
_PLACED = re.compile(
    r"\b(?:(?:that|which) (?:is|are|sits?|rests?|stands?|lies|lie)|sitting|resting|standing|lying|located|perched|"
    r"placed|kept|parked|positioned)(?: (?:up|down|over|back|right))? (?:on|in|inside|on top of|at|by|near|next to|"
    r"beside|between|under)\b"
)
# Prepositions that only say where a thing goes; "on", "in", "inside", "on top of" may also say where it is.
_STRONG = ("onto", "on to", "into")


def _destination_first(rest: str) -> str:
    """ "put on the plate the black bowl", "place into the basket whichever box is nearest": a destination said
    before the object is the same carry ("the black bowl onto the plate")."""
    m = re.fullmatch(
        r"(onto|on to|into|on top of|inside|in|on) ((?:the|a|an) (?:(?!the |a |an |whichever |any )\S+ )*?\S+) "
        r"((?:the|a|an|whichever|any|each|every) .+)",
        rest,
    )
    if not m:
        return rest
    prep = {"in": "into", "inside": "into", "on": "onto"}.get(m.group(1), m.group(1))
    return f"{m.group(3)} {prep} {m.group(2)}"


def _destination(rest: str) -> tuple[str, str, str] | None:
    """(object words, relation, destination words), or None. The destination starts at the last preposition that
    can only say where a thing goes ("onto", "into"), else at the last destination preposition; one right after a
    locating verb ("that sits on", "resting on") says where a thing is, not where it goes."""
    matches = list(_DEST.finditer(rest))
    if not matches:
        return None
    free = [m for m in matches if not _LOCATIVE_BEFORE.search(rest[: m.start()])] or matches
    strong = [m for m in free if m.group(1) in _STRONG]
    m = (strong or free)[-1]
    # "put it on the plate on top of the box": a pronoun is located by nothing, so its first preposition says
    # where it goes and what follows locates the destination
    if re.fullmatch(r"(?:it|them)", rest[: free[0].start()].strip()) and not strong:
        m = free[0]
    prep, obj, target = m.group(1), re.sub(r"\s+and$", "", rest[: m.start()].strip()), rest[m.end() :].strip()
    if not target:
        return obj, ("in" if prep in IN else "on"), ""
    if prep in ("to the front of", "in front of"):
        return obj, "near", target
    if prep == "to the top of":
        return obj, "on", f"top of {target}"
    if prep == "to":
        return obj, ("in" if noun_phrase(target).split()[-1:] in ([c] for c in CONTAINERS) else "on"), target
    return obj, ("in" if prep in IN else _RELATION_OF.get(prep, "on")), target


# "the red block (sitting) to the right of the blue block": where the thing is, not where it goes ("lift the red block
# to the right of the blue block" lifts it; "take ... to the right of ..." without a participle carries it)
_SIDE_OF_THING = re.compile(
    r"\b(?:(?:sitting|resting|standing|lying|located|placed|kept|(?:that|which) (?:is|sits|stands|rests|lies)|is) )"
    r"(?:just |right |directly )?to (?:the )?(?:left|right)(?:[- ]hand)?(?: side)? of\b"
)


def _clause(action: str, rest: str, text: str, antecedent: str | None = None, last_target: str | None = None) -> Clause:
    particle = PARTICLE_VERBS.get(action)
    if particle and rest.endswith(" " + particle):
        rest = rest[: -len(particle) - 1]
    if action == "pick" and rest.startswith("up "):
        rest = rest[3:]
    rest = re.sub(r"\s+down(?=\s+(?:on|onto|in|into|from|with|to|there|here)\b|$)|^down\s+", " ", rest).strip()
    if action == "put":  # "carry it to the rack and set it down there": the place said before, no new one
        rest = re.sub(r"^(it|them)\s+(?:there|here)$", r"\1", rest)
    # "over to", "across onto", "back into": the particle adds nothing to where it goes
    rest = re.sub(r"\b(?:over|across|back|away|off|up) (?=(?:to|onto|into|on to|in|on|inside|on top of)\b)", "", rest)
    rest = re.sub(r"\s+in front of (?:it|them)$", "", rest)
    distance, rest = _distance(rest)
    direction = None
    if action == "push":  # elsewhere "left" and "closer" pick out an object, not a way to move it
        direction, rest = _direction(rest)
    carried = action == "put" or (
        action == "pick" and re.search(r"\b(?:into|in|onto|on|over)\s+(?:the|a|an)\b", rest) is not None
    )  # ("take the beads from the mug into the bowl": a pick verb with a destination)
    if carried and re.match(rf"{CONTENTS_SAID}(?:{'|'.join(CONTENTS)})\b", rest):
        action = "pour"  # "beads -> bowl": what a container holds goes in by pouring it out of the container
    if action == "mention":
        # "there's a drawer sticking out": how it stands is no part of its name
        rest = re.sub(
            r" (?:is |are )?(?:sticking|poking|hanging|standing|sitting|lying) (?:out|open|up|there|here)$", "", rest
        )
        return Clause(action, obj=object_phrase(rest) or None, text=text)
    if action == "scrub":
        # "scrubbed good / well": how well is no part of what is scrubbed
        rest = re.sub(r"\s+(?:good|well|properly|thoroughly|nicely|really well|really good)\b", "", rest)
        split = _split_on(rest, WITH)
        if not split:  # "scrubbed by the sponge": the passive's agent is the tool
            agent = re.fullmatch(
                r"(.+?) by ((?:the|a|an|that|this) (?:\w+ )?(?:sponge|brush|cloth|rag|towel|scrubber|pad))", rest
            )
            split = (agent.group(1), agent.group(2)) if agent else None
        obj, tool = split if split else (rest, None)
        rubbed = (
            None
            if split
            else re.fullmatch(r"(it|them|(?:the |a |an )?\w+(?: \w+)?) (?:all )?(?:over|across) (.+)", rest)
        )
        if rubbed:  # "rub it all over the plate": what is rubbed is the tool, where it goes is scrubbed
            return Clause(action, target=noun_phrase(rubbed.group(2)), tool=noun_phrase(rubbed.group(1)), text=text)
        off = _split_on(obj, ("off of", "off", "from"))
        obj = re.sub(r"\s+(?:clean|down)$", "", off[0] if off else obj)  # "wipe the dirt off the table": the dirt
        if not split and obj.removeprefix("the ") in TABLE:  # "wipe the table", "table clean": the dirt on it
            obj = f"dirt on {obj.removeprefix('the ')}"
        # the tool may be named by where it is ("with the sponge lying to the right of the plate")
        return Clause(action, target=noun_phrase(obj), tool=object_phrase(tool) if tool else None, text=text)
    if action == "pour":
        into = _split_on(rest, IN) or _split_on(rest, ON)
        if not into:  # "from the mug to the bowl", "the beads of the cup to the bowl": "to" says where they go
            to = re.fullmatch(r"(.+?) (?:over |across |back )?to (?!(?:the |your )?(?:left|right|side)\b)(.+)", rest)
            into = (to.group(1), to.group(2)) if to else None
        later = [m for m in re.finditer(r"(?:^|\s)in(?:to|side)?(?=\s)", rest)][1:]
        if into and not re.search(r"\binto\b", rest) and later:
            # "the beads in the mug in the bowl": where they are said first, where they go last
            into = (rest[: later[-1].start()].strip(), rest[later[-1].end() :].strip())
        what, target = into if into else (rest, None)
        what = re.sub(r"(?<=\w) (?:out|over|away)$", "", what)  # "tip them out into the bowl": the verb's particle
        src = _split_on(what, FROM) or _contents_of(what)
        obj, source = src if src else (what, None)
        source = noun_phrase(source) if source else _holder(obj) or noun_phrase(obj)
        if target and source:  # "from the mug on your right into the one on your left": of the source's kind
            target = _elided_noun(target, source)
        return Clause(
            action,
            obj=noun_phrase(obj) if obj else None,
            target=object_phrase(target) if target else None,  # "the bowl on the tray": located, not a "tray bowl"
            source=source,
            text=text,
        )
    if action == "pick":
        handed = re.fullmatch(r"(.+?) with the (right|left|one) arm for the (right|left|other) arm", rest)
        if handed:  # rewritten from "pick up X with one arm and hand it to the other arm"
            return Clause(
                action, obj=object_phrase(handed.group(1)), arm=handed.group(2), to_arm=handed.group(3), text=text
            )
        both = re.fullmatch(r"(.+ handle) with (?:both|two) arms", rest)
        if both:  # a handle of something lifted with both arms: its own arm grips it, the other arm the other one
            return Clause(action, obj=object_phrase(both.group(1)), together=True, text=text)
        # "grab the ketchup for the basket": a thing fetched for a place is carried there
        rest = re.sub(r"\s+for (the|a|an) (?=\w)", r" to \1 ", rest)
        # "take the block into the basket": a destination makes it a carry; "pick the bowl on the stove": where
        # it is picks out which bowl, and stays in the phrase
        # "get it on top of the green cube": a pronoun is located by nothing, so a place after it is where it goes
        placed = re.match(r"(?:it|them) (?:on top of|on|in|inside)\s", rest)
        if not placed and not re.search(r"(?<!next )(?<!close )\b(into|onto|to)\b", _SIDE_OF_THING.sub("", rest)):
            return Clause(action, obj=object_phrase(rest) or None, direction=direction, distance_m=distance, text=text)
        action = "put"
    if action in ("open", "close", "turn_on", "turn_off"):
        rest = re.sub(r"^(it|them|that one|this one) (?:up|back up|right up)$", r"\1", rest)  # "open it up"
        return Clause(action, obj=noun_phrase(rest) or None, text=text)
    if action == "push" and not re.search(r"\b(into|onto|in|on)\b", rest):
        split = _split_on(rest, ("to the front of", "next to", "to", "toward", "towards", "beside"))
        if split:
            obj, target = split
            return Clause(
                action,
                obj=object_phrase(obj),
                target=noun_phrase(target),
                relation="near",
                direction=direction,
                distance_m=distance,
                text=text,
            )
        return Clause(action, obj=object_phrase(rest) or None, direction=direction, distance_m=distance, text=text)
    dest = _destination(_destination_first(rest))
    if dest:
        obj, relation, target = dest
        said = object_phrase(obj) if obj else ""
        # "balance it on the blue one": "one" stands for the noun of what "it" stands for
        kind = antecedent if is_pronoun(said) and antecedent else said
        # "the red block in the green tray and the blue block in the yellow one": in parallel with the last
        # destination said by its colour or size, "one" is of that destination's kind
        # ("... in the tray that isn't yellow, and the blue block in the one that isn't green": the tray's too)
        said_as = last_target.split() if last_target and not is_pronoun(last_target) else []
        if len(said_as) > 1 and set(said_as) & _ATTRIBUTE_WORDS:
            kind = " ".join(said_as)
        # "on top of that (one)": a pronoun, for the clause before to resolve
        target = "it" if target in ("that", "this", "that one", "this one") else _elided_noun(target, kind)
        # "the plate that sits on the cookie box": a destination located by what it rests on reads as an object does
        # "onto the peg to the left of the round peg" too: where it stands, not "of" a part
        located = (
            _PLACED.search(target)
            or BESIDE.search(target)
            or (is_pronoun(said) and re.search(r"\s(?:on top of|on|in|inside|next to|beside|near|by)\s", target))
        )
        return Clause(
            action,
            obj=object_phrase(obj) or None,
            target=(object_phrase(target) if located else noun_phrase(target)) or None,
            relation=relation,
            direction=direction,
            distance_m=distance,
            text=text,
        )
    return Clause(action, obj=object_phrase(rest) or None, direction=direction, distance_m=distance, text=text)


def _holder(phrase: str) -> str | None:
    """ "the beads (that are sitting) in the red mug": what holds what is poured is where it is poured from."""
    m = re.fullmatch(
        rf"(?:(?:the|a|an|all the|all) )?(?:{'|'.join(CONTENTS)})\s+(?:(?:that|which) )?(?:are |is )?"
        r"(?:sitting |resting |lying |kept )?(?:in|inside|from|out of) (.+)",
        phrase.strip(),
    )
    return noun_phrase(m.group(1)) if m else None


def _elided_noun(target: str, obj: str) -> str:
    """ "one" stands for the noun just named: "put the farther block onto the nearer one" -> "... nearest block";
    "stack the red block on the blue one" -> "blue block"; "onto the one that isn't red" -> "block not red"."""
    head = re.split(r" not ", split_relation(obj)[0])[0].split() if obj else []
    if head and (head[-1] in BASE_COLOURS or head[-1] in SIZES):
        return target  # "the red one ... the green one": the kind is the scene's to find, no colour is a noun
    said = re.fullmatch(
        r"(?:the )?one ((?:that|which) .+|(?:on|to|at) (?:the |your )?(?:left|right|back|front)\b.*)", target
    )
    if said and head:  # "onto the one that isn't red", "into the one on your left": one of the kind just named
        return object_phrase(f"{head[-1]} {said.group(1)}")
    m = re.fullmatch(r"(.*\S)\s+ones?", target)
    if not m or not obj or m.group(1) in ("the", "that", "this", "the other", "other"):
        return target
    return f"{m.group(1)} {head[-1]}" if head else target


def is_pronoun(phrase: str | None) -> bool:
    return phrase is not None and phrase in PRONOUNS


def _contents_of(phrase: str) -> tuple[str, str] | None:
    """ "tiny yellow beads of the red cup": the beads, and the cup they are poured from."""
    m = re.fullmatch(r"(.*\b(?:beads|marbles|balls|contents|water|rice|grains))\s+of (.+)", phrase)
    return (m.group(1), m.group(2)) if m else None
