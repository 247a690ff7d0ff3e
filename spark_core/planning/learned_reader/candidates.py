"""The goals a scene view affords, each as clauses the rules planner composes and as one plain sentence.

The frames are the grammar's single goals and the two-goal shapes the task catalog's instructions have (open a
thing then put another in it; two moves one after the other). Every slot is filled with phrases perception found
for the instruction, so no candidate names a thing the scene does not hold."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from itertools import permutations

from ...perception.qualifiers import SUPPORT_RELATIONS, split_relation
from ..rules.parse import Clause

_FIXTURE = ("open", "close", "turn_on", "turn_off")
_SAID = {"open": "open", "close": "close", "turn_on": "turn on", "turn_off": "turn off"}
MAX_PHRASES = 6  # more found phrases than this: the fallback does not enumerate (a sentence of many things)


@dataclass(frozen=True)
class Candidate:
    clauses: tuple[Clause, ...]
    text: str  # the goal said plainly, as the scorer reads it


def _say(c: Clause) -> str:
    if c.action in _FIXTURE:
        return f"{_SAID[c.action]} the {c.obj}"
    if c.action == "pick" and c.together:
        return f"lift the {c.obj} with both arms"  # one of two handles
    if c.action == "pick" and c.to_arm:
        return f"pick up the {c.obj} and hand it to the {c.to_arm} arm"
    if c.action == "pick":
        return f"pick up the {c.obj}"
    if c.action == "push":
        where = "into" if c.relation == "in" else "to the front of"
        return f"push the {c.obj} {where} the {c.target}"
    if c.action == "pour":
        source = f" from the {c.source}" if c.source else ""
        return f"pour the {c.obj}{source} into the {c.target}"
    if c.action == "scrub":
        return f"scrub the {c.target} with the {c.tool}" if c.tool else f"wipe the {c.target}"
    return f"put the {c.obj} {c.relation} the {c.target}"


def _stands_on(phrase: str) -> list[str]:
    """What the phrase says its thing stands on or in ("cookie box" of "bowl on cookie box")."""
    _, relation, anchors = split_relation(phrase)
    return anchors if relation in SUPPORT_RELATIONS else []


def singles(phrases: list[str]) -> list[Candidate]:
    """One goal over the found phrases: a pick, a fixture's action, a move onto or into another, a push, a pour,
    a scrub, a two-armed lift or a handover."""
    out: list[tuple[Clause, ...]] = []
    for a in phrases:
        out += [(Clause("pick", obj=a),), (Clause("scrub", target=a),)]
        out += [(Clause(action, obj=a),) for action in _FIXTURE]
        out += [(Clause("pick", obj=a, arm="one", to_arm="other"),)]
    for a, b in permutations(phrases, 2):
        if b not in _stands_on(a):  # "the bowl on the cookie box" put on the cookie box: where it already is
            out += [(Clause("put", obj=a, target=b, relation="in"),), (Clause("put", obj=a, target=b, relation="on"),)]
        out += [(Clause("push", obj=a, target=b, relation="in", direction="forward"),)]
        out += [(Clause("push", obj=a, target=b, relation="near"),)]
        out += [(Clause("pour", obj=a, target=b),), (Clause("scrub", target=b, tool=a),)]
        out += [(Clause("pick", obj=a, together=True), Clause("pick", obj=b, together=True))]
    for a, b, c in permutations(phrases, 3):
        out += [(Clause("pour", obj=a, source=b, target=c),)]
    return [Candidate(c, said(c)) for c in out]


def pairs(first: list[Candidate], phrases: list[str]) -> list[Candidate]:
    """Two goals one after the other, from single goals: two moves, or an opening then a move into what was
    opened."""
    out: list[Candidate] = []
    moves = [c for c in first if c.clauses[0].action == "put"]
    for m, n in permutations(moves, 2):
        if m.clauses[0].obj != n.clauses[0].obj:
            out.append(Candidate(m.clauses + n.clauses, f"{m.text}, then {n.text}"))
    for d in phrases:
        for m in moves:
            if m.clauses[0].target == d and m.clauses[0].relation == "in":
                opened = Clause("open", obj=d)
                out.append(Candidate((opened, *m.clauses), f"{_say(opened)}, then {m.text}"))
    return out


def said(clauses: tuple[Clause, ...]) -> str:
    """The candidate's goal in plain words, as the scorer reads it."""
    if len(clauses) == 2 and all(c.together for c in clauses):
        return f"lift the {clauses[0].obj} and the {clauses[1].obj} together with both arms"
    return ", then ".join(_say(c) for c in clauses)


def options(
    phrases: list[str], compose: Callable[[list[Clause]], list[dict]], effect: Callable[[list[dict]], tuple]
) -> list[tuple[Candidate, list[dict]]]:
    """The candidates that compose (`compose` raises ValueError for those the planner's checks refuse), one per
    distinct effect, single goals first; nothing when perception found more phrases than `MAX_PHRASES`."""
    if len(phrases) > MAX_PHRASES:
        return []
    out: dict[tuple, tuple[Candidate, list[dict]]] = {}
    for c in singles(phrases):
        try:
            children = compose(list(c.clauses))
        except ValueError:
            continue
        out.setdefault(effect(children), (c, children))
    composed = {c: children for c, children in out.values()}
    for c in pairs(list(composed), phrases):
        if c.clauses[0].action == "open":
            try:
                children = compose(list(c.clauses))
            except ValueError:
                continue
        else:  # two moves: the first's steps, then the second's (each already checked on its own)
            one, two = (composed[Candidate((k,), _say(k))] for k in c.clauses)
            children = [s for s in one if s.get("primitive") != "go_home"] + two
        out.setdefault(effect(children), (c, children))
    return list(out.values())
