"""A plan whose instruction also asks for the opposite of what the plan does: refused, whichever reading planned it.

"put the orange juice in the basket and also keep it out of the basket", "turn the stove off and leave it on", "lift
the red cube and leave it resting on the table", "put the red cube on the green cube while the green cube stays on top
of the red cube", "push the plate to the front of the stove and behind it at the same time": each reading of the
planner (the rules, the order-free reader, the scene's affordances, the learned reader) reads the request and passes
over the clause that undoes it. The plan's own steps say what it does; this module looks in the words for a state
said of the same thing that cannot hold with it.
"""

from __future__ import annotations

import re

from ...perception.qualifiers import split_relation

# Said to hold at once: two opposite relations or states joined by one of these cannot both be met.
# (not "at once": "immediately"; "while keeping it": said of the same thing)
_AT_ONCE = re.compile(
    r"\b(?:at (?:the )?same (?:time|moment)|in (?:the )?same (?:moment|time|instant)|simultaneously|both at once|"
    r"while (?:keeping|leaving|having) it)\b"
)
_OPPOSED = (
    (r"\bin front of\b|\bto the front\b|\bfront of\b", r"\bbehind\b|\bback of\b"),
    (r"\bopen(?:ed)?\b", r"\bclosed?\b|\bshut\b"),
    (r"\bon top of\b|\babove\b|\batop\b", r"\bunder(?:neath)?\b|\bbelow\b|\bbeneath\b"),
    # "turn the stove off and at the same time turn it on" (the same thing: "it" said of it)
    (r"\b(?:turn|switch)\w* (?:\w+ ){0,3}?off\b", r"\b(?:turn|switch)\w* (?:it on|on it)\b"),
    (r"\b(?:turn|switch)\w* (?:\w+ ){0,3}?on\b", r"\b(?:turn|switch)\w* (?:it off|off it)\b"),
)
# Keeping a thing in a state: the verbs that say it, before the thing ("keep it ...") or after it ("it stays ...").
_KEEP = r"(?:keep|keeping|keeps|leave|leaving|leaves)"
_STAY = r"(?:stays?|staying|remains?|remaining|is kept|is left)"
_MAY = r"(?:can |should |will |must |has to |needs to )?"
_AWAY = r"(?:out of|outside(?: of)?|away from|off)"
_SWITCHED = r"(?:stove|burner|hob|cooker|cooktop|oven|range|heat|knob|dial|lamp|light)"
# where a thing already is: "exactly where it is", "in place", "put"
_IN_PLACE = r"(?:exactly |just |right )?(?:where it (?:is|was|sits|stands)|in (?:its )?place|put|unmoved)\b"
_NOUN = r"(?:the|top|a|an|its|it)\b"  # "leave it on the plate": a place, not a state
_WHILE = r" the(?= (?:whole|entire) time\b)"  # "keep it off the whole time": how long, not where
_NOT_TO_DO = re.compile(r"\b(?:don't|dont|do not|not|never|rather than|instead of|no)\s+(?:\w+\s+)?$")


def _thing(label: str, other: str | None = None, pronoun: bool = True) -> str:
    """A pattern for a plan label as said: "it" (unless not `pronoun`), or "the" and the label's head noun (of the
    thing, not of what it is located by: "red cube under green") with only words of the label before it (so "the
    other black bowl" is never the black bowl planned); when the other label shares the head ("red cube", "green
    cube") the word before the head must be said too."""
    words, others = _own(label).split(), _own(other).split() if other else []
    head = re.escape(words[-1])
    if others[-1:] == words[-1:] and len(words) > 1:
        head = rf"{re.escape(words[-2])} {head}"
    said = "|".join(re.escape(w) for w in words[:-1] if w not in ("and", "or", "the"))
    before = rf"(?:(?:{said}) ){{0,2}}" if said else ""
    return rf"(?:it|the {before}{head})" if pronoun else rf"(?:the {before}{head})"


def _worked(label: str, parts: tuple[str, ...], kinds: str) -> str:
    """A pattern for the thing a knob or handle label works, as said: "it", or "the" and the label's words without
    the part ("top drawer handle" -> "the top drawer"), else the kind alone with no word before it ("the stove")."""
    words = [w for w in _own(label).split() if w not in parts]
    named = rf"the (?:(?:{'|'.join(map(re.escape, words[:-1]))}) ){{0,2}}{re.escape(words[-1])}" if words else ""
    return rf"(?:it|{named}|the {kinds})" if named else rf"(?:it|the {kinds})"


def _own(label: str) -> str:
    """The words of a label that name the thing itself: "red cube under green" -> "red cube", "block not blue" ->
    "block"."""
    return re.split(r"\s+not\s+", split_relation(label)[0])[0] or label


def _moves(
    steps: list[dict],
) -> tuple[list[tuple[str, str]], list[str], list[tuple[str, float]], list[tuple[str, float]]]:
    """(thing, where it is set down) for each move, the things picked and not set down, (knob, angle) of each turn,
    (handle, end state: +1 open, -1 closed) of each drawer worked."""
    moves: list[tuple[str, str]] = []
    lifted: list[str] = []
    turns: list[tuple[str, float]] = []
    drawers: list[tuple[str, float]] = []
    held: str | None = None
    for step in steps:
        p, params = step.get("primitive"), step.get("params", {})
        if p in ("pick", "grasp_se3"):
            held = params.get("keypoint_label")
        elif p == "stack":
            moves.append((params["keypoint_label"], params["target_label"]))
            held = None
        elif p in ("place", "place_in") and held:
            moves.append((held, params.get("target_label") or params.get("container_label") or ""))
            held = None
        elif p == "push_object":  # pushed somewhere: moved, though nothing is set down
            moves.append((params.get("keypoint_label", ""), ""))
        elif p == "turn_knob":
            turns.append((params.get("keypoint_label", ""), float(params.get("angle", 0.0))))
        elif p in ("open_drawer", "close_drawer"):
            drawers.append((params.get("keypoint_label", ""), 1.0 if p == "open_drawer" else -1.0))
    if held:
        lifted.append(held)
    return moves, lifted, turns, drawers


def contradicted(instruction: str, steps: list[dict]) -> str | None:
    """The words of `instruction` that ask for the opposite of what `steps` (a plan's leaves, in order) do, or None."""
    text = " ".join(re.sub(r"[^a-z0-9' ]", " ", instruction.lower()).split())
    if _AT_ONCE.search(text):
        if m := re.search(r"\b(?:on and off|off and on|open and (?:closed?|shut)|(?:closed?|shut) and open)\b", text):
            return f"{m.group(0)} at once"
        for a, b in _OPPOSED:
            if (m := re.search(a, text)) and (n := re.search(b, text)):
                return f"{m.group(0)} ... {n.group(0)} at once"
    # "on the plate and underneath the plate", "both inside and outside of it": two opposite places of one thing
    if m := re.search(r"\b(?:on|on top of|above) (the (?:\w+ )?\w+) and (?:under|underneath|below|beneath) \1\b", text):
        return m.group(0)
    if m := re.search(r"\bboth (?:inside|in) and (?:outside|out)\b|\bboth (?:open|opened) and (?:closed|shut)\b", text):
        return m.group(0)
    # "in the basket and at the same time not in the basket": a place and its negation
    m = re.search(
        r"\b(in|into|inside|on|onto|on top of) (the (?:\w+ )?\w+)\b.*?\bnot (?:in|into|inside|on|onto|on top of) \2\b",
        text,
    )
    if m and (m.group(1) in ("in", "into", "inside")) == bool(re.search(r"not (?:in|into|inside) ", m.group(0))):
        return m.group(0)
    # "put the butter in the basket without moving the butter": a thing carried that may not move
    if m := re.search(
        r"\b(?:put|place|move|lift|pick|take|carry|bring|set|drop|push|slide|raise)\w* (?:up )?(?:the |a |an )?"
        r"((?!(?:the|a|an)\b)(?:\w+ )?\w+)\b.*\bwithout (?:moving|touching|displacing|shifting) "
        r"(?:it|them|the \1|\1)\b",
        text,
    ):
        return m.group(0)
    # "put the cream cheese in the basket that is inside the cream cheese": a place inside the thing put there
    if m := re.search(
        r"\b(?:put|place|drop|set|move|stand|stick)\w* (?:the )?((?:\w+ )?\w+) (?:in|into|inside|on|onto|on top of) "
        r"(?:the )?(?:\w+ )?\w+ (?:that is |that s |which is |sitting |standing |lying )?"
        r"(?:in|inside|on|on top of|under) (?:the )?\1\b",
        text,
    ):
        return m.group(0)
    # "hand the hammer from the left arm to the left arm": a hand-over to the arm that holds it
    if m := re.search(
        r"\b(?:from|with|in) (?:the |your |its )?(left|right) (?:arm|hand|gripper)\b.*?\b(?:to|into|over to|across to) "
        r"(?:the |your )?\1 (?:arm|hand|gripper)\b",
        text,
    ):
        return m.group(0)
    if said := _taken_back(text):
        return said
    if m := re.search(
        r"\b(?:turn|turns|turning|change|convert|transform|morph)\b(?: \w+){1,4}? into (?:a|an|some) \w+", text
    ):
        return m.group(0)  # "turn the stove into a wine bottle": a thing made another, which no step does
    moves, lifted, turns, drawers = _moves(steps)
    for thing, dest in moves:
        if not dest:  # a push: no place set down on, but moved all the same
            if m := _said(rf"\b(?:also|but|yet|while) (?:\w+ )?{_KEEP} {_thing(thing)} {_IN_PLACE}", text):
                return m.group(0)
            continue
        x, t = _thing(thing, dest), _thing(dest, thing)
        # the destination moved onto the thing by a step of the plan itself: the planner's own check sees that order
        reversed_too = any(_names(m, dest, thing) and _names(d, thing, dest) for m, d in moves)
        for pattern in (
            rf"\b{_KEEP} {x} {_AWAY} {t}",  # "... and also keep it out of the basket"
            rf"\b{x} {_STAY} {_AWAY} {t}",
            *([] if reversed_too else [_reverse(_thing(dest, thing, pronoun=False), x)]),
            # "... and also leave it exactly where it is": said beside the move, not after it ("then leave it there")
            rf"\b(?:also|but|yet|while) (?:\w+ )?{_KEEP} {x} {_IN_PLACE}",
            # "... while making sure it never touches the plate": set down on it, never touching it
            rf"\b{x} (?:never|doesn't|does not|won't|will not|must not|mustn't|should not|shouldn't) touch(?:es)? {t}",
            rf"\bwithout (?:it |ever )?touching {t}",
            rf"\bwithout (?:ever |even )?touching {x}",
        ):
            if m := _said(pattern, text):
                return m.group(0)
    for thing in lifted:
        x = _thing(thing)
        for pattern in (
            rf"\b{_KEEP} {x} (?:\w+ )?on the (?:table|counter|worktop|floor)\b",  # "lift it and leave it on the table"
            rf"\b{x} {_STAY} (?:\w+ )?on the (?:table|counter|worktop|floor)\b",
            rf"\bwithout (?:lifting|raising|picking) {x}",
            rf"\bwithout (?:ever |even )?touching {x}",  # "lift the red cube without touching it"
        ):
            if m := _said(pattern, text):
                return m.group(0)
    for knob, angle in turns:
        state = "off" if angle > 0 else "on"  # the opposite of the turn's own end state
        it = _worked(knob, ("knob", "dial", "switch"), _SWITCHED)
        # ("keep it switched off the whole time"; "leave it on the plate" names a place)
        if m := _said(
            rf"\b(?:{_KEEP} {it}|{it} {_MAY}{_STAY}) (?:switched |turned )?{state}\b(?! {_NOUN}(?<!{_WHILE}))", text
        ):
            return m.group(0)
    for handle, sense in drawers:
        state = r"(?:closed|shut)" if sense > 0 else r"open"
        it = _worked(handle, ("handle",), "drawer")
        if m := _said(rf"\b(?:{_KEEP} {it}|{it} {_MAY}{_STAY}) (?:\w+ )?{state}\b", text):
            return m.group(0)
    return None


def _taken_back(text: str) -> str | None:
    """A request said and then said not to be done, word for word ("open the drawer but don't open the drawer")."""
    said = [c.strip() for c in re.split(r"\b(?:but|and|yet|then|while)\b", text) if c.strip()]
    for i, clause in enumerate(said):
        m = re.fullmatch(r"(?:also |please |just )?(?:don't|dont|do not|never) (.+)", clause)
        if m and any(_plain(m.group(1)) == _plain(c) for c in said[:i]):
            return f"{said[i - 1]} but {clause}"
    return None


def _plain(clause: str) -> str:
    return re.sub(r"^(?:please |also |just |first |then )+", "", clause).strip()


def _names(label: str, meant: str, other: str) -> bool:
    """`label` names the thing `meant`: its head noun, or the whole label when `other` has the same head ("red cube"
    and "green cube")."""
    if meant.split()[-1:] == other.split()[-1:]:
        return label == meant
    return label.split()[-1:] == meant.split()[-1:]


def _reverse(t: str, x: str) -> str:
    """The destination said to rest on or in the thing carried ("... while the green cube stays on top of it")."""
    return (
        rf"\b{t} (?:{_STAY}|is|rests|resting|sits|sitting)(?: stacked| sitting| resting| lying| placed)? "
        rf"(?:on top of|atop|on|in|inside) {x}\b"
    )


def _said(pattern: str, text: str) -> re.Match | None:
    """The first match of `pattern` in `text` not said as what not to do ("don't leave the stove on; turn it off",
    "rather than leaving it on the table")."""
    for m in re.finditer(pattern, text):
        if not _NOT_TO_DO.search(text[: m.start()]):
            return m
    return None
