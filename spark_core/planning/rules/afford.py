"""The reading the scene affords: a fallback for single-step requests the rule parser and the order-free reader
both refuse, that finds the goal from meaning rather than from where the words stand.

The goals a scene affords are few: pick a thing up, put a thing on or in another, open or close what has a
handle, turn on or off what has a knob. This module reads the instruction loosely into

- mentions: every run of words that names something (a noun with its describing words, as perception reads a
  phrase), with the cue its own preposition gives ("into" a destination, "from" where it is now, "next to" what
  locates it); a word the sentence says the goal with ("opened", "raised", "shut") ends a mention instead of being
  swallowed by it ("get the cabinet drawer opened up": the drawer, and "opened");
- cues: the actions its verbs, participles and goal-state words name (the lexicon's), and whether it states a goal;

then grounds every mention in what perception found for it (observe looks for each: `phrases`), enumerates the
readings the grounded things afford (each a pick, a move of one onto or into another, or a fixture's action) and
scores each against the cues: roles from prepositions, which thing can hold or support another (a container, a
support) and which is a fixture that is never carried, which is said first. The best reading is planned only when

- every mention is grounded (the safety rule: a thing the scene does not hold is never planned around; several
  matches are an ambiguity), and every word perception was asked for and found nothing for is a word of some
  grounded mention (what another reading of the sentence could not place is placed here, or the request refuses);
- it wins clearly: no other reading with a different effect scores within `MARGIN` of it;
- it composes through the planner's own checks (rules/planner.py `_compose`: kinds, near-miss names, nothing put on
  itself).

Negation, questions and several steps are left to the rule parser: this reads one goal."""

from __future__ import annotations

import re
from dataclasses import dataclass

from lemminflect import getAllLemmas

from .frames import leading_verb
from .lexicon import CONTAINERS, CONTENTS, DETERMINERS, FILLERS, HELD, PARTICIPLES, REGIONS, STATE_ACTIONS, VERBS
from .mentions import ABSTRACT, ATTRIBUTES
from .parse import Clause
from .phrases import object_phrase, singular
from .reader import (
    _BREAK,
    _NEGATION,
    _QUESTION,
    _WAYS,
    _closed,
    _starts_preposition,
    _tokens,
    _verb_spans,
    intent,
    preposition_at,
)
from .things import adverb_only

# Quantifiers said before a thing ("every bead", "each block"): they count, they name nothing.
_QUANTIFIERS = frozenset(["every", "each", "any", "whole", "entire", "all", "both"])
# Things that hold or carry another: a destination.
SUPPORTS = frozenset(
    [*CONTAINERS, "plate", "dish", "tray", "rack", "cabinet", "cupboard", "shelf", "stove", "cooktop", "burner", "hob"]
    + ["peg", "rod", "post", "saucer", "platter", "board", "block", "cube", "brick", "top", "area", "zone"]
)
# Things that stand where they are: never what is carried.
FIXTURES = frozenset(
    ["stove", "cooktop", "burner", "hob", "cooker", "cabinet", "cupboard", "rack", "shelf", "drawer", "peg", "rod"]
    + ["post", "table", "area", "zone", "counter", "sink"]
)
# Goal-state words that say what is to become of the thing (the lexicon's, one word each).
_STATE_WORDS = {s: a for s, a in STATE_ACTIONS if " " not in s and s not in ("on", "off", "open")}
_HELD_WORDS = {h for h in HELD if " " not in h and h != "up"}
_CONTENTS = frozenset(singular(c) for c in CONTENTS)
# Words that frame a request or a wish, with no thing or action of their own ("would love to see", "it wants").
_FRAMING = frozenset(
    ["love", "loves", "like", "likes", "wants", "wanted", "hope", "prefer", "mind", "see", "seeing", "have", "has"]
    + ["make", "makes", "let", "lets", "after"]
)
_FILLER_WORDS = frozenset(f for f in FILLERS if " " not in f)
# Verbs of wanting, seeing to it and ending up: they frame a goal, they ask no other doing of the robot.
_WISHING = frozenset(
    ["want", "need", "like", "love", "wish", "hope", "prefer", "see", "let", "make", "ensure", "help", "try", "mean"]
    + ["think", "guess", "reckon", "suppose", "believe", "know", "seem", "appear", "require", "expect", "end", "wind"]
    + ["finish", "land", "stay", "remain", "sit", "rest", "stand", "lie", "belong", "go", "get", "leave", "keep", "be"]
    + ["do", "have", "can", "could", "would", "should", "must", "will", "shall", "may", "might", "use", "manage"]
)


def _known_verbs() -> frozenset[str]:
    """The lemmas of every word of the lexicon's verbs and goal words, and the verbs that frame a goal."""
    words = {w for forms in VERBS.values() for f in forms for w in f.split()}
    words |= {w for p in PARTICIPLES for w in p.split()} | {w for s, _ in STATE_ACTIONS for w in s.split()}
    lemmas = {lemma for w in words for ls in getAllLemmas(w).values() for lemma in ls}
    return frozenset(words | lemmas | _WISHING | _FRAMING)


_KNOWN_VERBS = _known_verbs()


def asks_other_doing(tokens: list[str]) -> str | None:
    """A word only ever a verb that no verb of the lexicon is, nor one of wanting or ending up ("teach the sponge to
    sing to the plate"): the sentence asks for a doing the robot has no word for, and reading it by what the scene
    affords would plan something else. None when there is none."""
    for t in tokens:
        lemmas = getAllLemmas(t)
        if set(lemmas) != {"VERB"} or t in _KNOWN_VERBS or t in _FILLER_WORDS:
            continue
        if not {lemma for ls in lemmas.values() for lemma in ls} & _KNOWN_VERBS:
            return t
    return None


MARGIN = 1.0
MAX_MENTIONS = 3


@dataclass(frozen=True)
class Mention:
    phrase: str  # as perception reads it
    role: str  # thing | dest | source | near | tool
    relation: str | None  # on | in (dest, source)
    start: int
    end: int = 0


@dataclass(frozen=True)
class Reading:
    clause: Clause
    score: float
    why: str


def _cue_positions(tokens: list[str]) -> dict[int, str]:
    """Token index -> the action a goal-state word there names ("opened", "shut", "raised", "stacked"); a word
    that frames the request ("love", "wants") or a verb the lexicon knows opening it ("crank the stove on") maps
    to "" (no action, no thing)."""
    out: dict[int, str] = {}
    lead = leading_verb(tokens)
    if lead is not None and not _verb_spans(tokens) & {lead} and tokens[lead + 1 : lead + 2] in (["the"], ["a"]):
        out[lead] = ""
    for n, t in enumerate(tokens):
        after = tokens[n + 1] if n + 1 < len(tokens) else ""
        if t in ("on", "off") and n and (not after or after == "," or after in _FILLER_WORDS):
            out[n] = "turn_on" if t == "on" else "turn_off"  # "crank the stove on": a state said last
        elif (phrasal := _phrasal_action(t, after)) is not None:
            out[n] = out[n + 1] = phrasal  # "switching on", "turned off"
        elif t in _FRAMING:
            out[n] = ""
        elif t in _STATE_WORDS:
            out[n] = _STATE_WORDS[t]
        elif t in _HELD_WORDS:
            out[n] = "pick"
        elif t in PARTICIPLES:
            out[n] = PARTICIPLES[t]
        elif t.endswith(("ed", "en", "ing")) and (action := _verb_action(t)):
            out[n] = action  # "stowed", "lifted", "tucked": the form of a verb the lexicon has
    return out


def _phrasal_action(word: str, particle: str) -> str | None:
    """The action of a two-word verb of the lexicon said in another form ("switching on" -> turn_on)."""
    if not particle or particle in ("the", "a", "an"):
        return None
    lemmas = getAllLemmas(word).get("VERB", ())
    return next((a for lemma in lemmas for a, forms in VERBS.items() if f"{lemma} {particle}" in forms), None)


def _verb_action(word: str) -> str | None:
    """The action of one of the planner's one-word verbs whose inflected form `word` is."""
    lemmas = getAllLemmas(word).get("VERB", ())
    return next((a for lemma in lemmas for a, forms in VERBS.items() if lemma in forms), None)


def mentions(instruction: str) -> tuple[list[Mention], list[str], bool] | None:
    """The mentions, the actions the cues name, and whether a goal is stated; None when the sentence is one this
    fallback leaves to the rule parser (negation, a question, words said twice, several steps' worth of things)."""
    tokens = _tokens(instruction)
    if set(tokens) & _NEGATION or any(t.endswith("n't") for t in tokens) or set(tokens) & _QUESTION:
        return None
    if asks_other_doing(tokens):
        return None
    if any(a == b for a, b in zip(tokens, tokens[1:])):
        return None
    stop = _verb_spans(tokens) | set(_cue_positions(tokens))
    fillers = {w for f in FILLERS for w in f.split()}
    found: list[Mention] = []

    def of(span: list[str], k: int) -> bool:  # "the drawer of the cabinet": one thing
        return bool(span) and tokens[k] == "of" and k + 1 < len(tokens) and tokens[k + 1] not in stop

    i = 0
    while i < len(tokens):
        role, relation, j = preposition_at(tokens, i)
        k = j
        while k < len(tokens) and (tokens[k] in DETERMINERS or tokens[k] in _QUANTIFIERS):
            k += 1
        span: list[str] = []
        while k < len(tokens) and k not in stop and tokens[k] != "," and (tokens[k] not in _BREAK or of(span, k)):
            if _starts_preposition(tokens, k):
                break
            if of(span, k):
                span.append("of")  # "the drawer of the cabinet": one thing
                k += 1
                while k < len(tokens) and tokens[k] in DETERMINERS:
                    k += 1
                continue
            if span and (tokens[k] in DETERMINERS or tokens[k] in _QUANTIFIERS):
                break
            span.append(tokens[k])
            k += 1
        while span and (span[-1] in fillers or span[-1] in ABSTRACT or adverb_only(span[-1]) or span[-1] in _WAYS):
            span.pop()
        while span and span[-1] == "of":
            span.pop()
        heads = [w for w in span if not _closed(w) or w in ATTRIBUTES]
        if heads and any(not _closed(w) for w in span):
            phrase = object_phrase(" ".join(span))
            if phrase:
                found.append(Mention(phrase, role, relation, i, k))
            i = k
            continue
        i = max(i + 1, k if k > j else j)
    found = _located(found, tokens)
    actions, goal = intent(tokens)
    states = set(_cue_positions(tokens).values()) - {""}
    if states & {"open", "close", "turn_on", "turn_off"} and set(tokens) & {"get", "gets", "getting", "have"}:
        actions.discard("pick")  # "get the drawer opened": a state brought about, nothing taken
    actions |= states
    # "turn the red block on like it's a burner": a switch verb first and its state after the thing switches
    if tokens[:1] in (["turn"], ["switch"], ["flick"], ["flip"]):
        state = next((t for t in tokens[2:6] if t in ("on", "off")), None)
        if state:
            actions.add(f"turn_{state}")
    if len(found) > MAX_MENTIONS:
        return None
    return found, sorted(actions), goal


# Words that say where a thing is, between it and the place ("the bowl sat on the stove").
_POSITION = frozenset(
    ["sat", "sitting", "sits", "resting", "rests", "standing", "stands", "lying", "lies", "located", "kept", "now"]
)


def _located(found: list[Mention], tokens: list[str]) -> list[Mention]:
    """A place said right after the thing (nothing or a word of position between) when another destination comes
    later is where the thing is, not where it goes: "the black bowl sat on the stove ... to the plate" is the
    black bowl on the stove (one phrase, as perception reads it), put on the plate."""
    out = list(found)
    for n in range(len(out) - 2):
        a, b = out[n], out[n + 1]
        later = [m for m in out[n + 2 :] if m.role == "dest"]
        between = [t for t in tokens[a.end : b.start] if t not in _POSITION]
        if a.role == "thing" and b.role == "dest" and b.relation in ("on", "in") and later and not between:
            merged = Mention(f"{a.phrase} {b.relation} {b.phrase}", "thing", None, a.start, b.end)
            return [*out[:n], merged, *out[n + 2 :]]
    return out


def unplaced_variety(instruction: str, labels: list[str], unresolved: dict[str, str]) -> str | None:
    """A mention perception found nothing for that a plan's label of the same kind stands in for although the
    mention says another colour, material or size ("the red block raised up onto the yellow block" read as a lift
    of the red block, where there is no yellow block): the mention, or None."""
    read = mentions(instruction)
    if read is None:
        return None
    for m in read[0]:
        if not unresolved.get(m.phrase, "").startswith("none"):
            continue
        said = {w for w in m.phrase.split() if w in ATTRIBUTES}
        for label in labels:
            if _head(label) == _head(m.phrase) and said - set(label.split()):
                return m.phrase
    return None


def phrases(instruction: str) -> list[str]:
    """What perception should look for so that this fallback can ground its mentions (observe.py, through
    reader.phrases): each mention, and the part a fixture's action grips when the sentence says one."""
    read = mentions(instruction)
    if read is None:
        return []
    found, actions, goal = read
    if not (actions or goal or any(m.role == "dest" for m in found)):
        return []  # nothing says what to do: no reading here, nothing to look for ("make the red block fly")
    out: dict[str, None] = {}
    fixture_only = not ({"put", "stack", "pick", "sort", "pour", "push"} & set(actions)) and len(found) == 1
    for m in found:
        out.setdefault(m.phrase, None)
        if {"open", "close"} & set(actions) and fixture_only:  # (the one reading that can use a handle)
            out.setdefault(f"{m.phrase} handle", None)
            if "drawer" in m.phrase.split():
                out.setdefault("drawer handle", None)
        if m.role == "dest" and "drawer" in m.phrase.split():  # into a drawer: opened first, by its handle
            out.setdefault(f"{m.phrase} handle", None)
            out.setdefault("drawer handle", None)
        if {"turn_on", "turn_off"} & set(actions) and fixture_only:
            out.setdefault(f"{m.phrase} knob", None)
    return list(out)


def _head(phrase: str) -> str:
    return singular(re.split(r"\s+(?:not|on|in|next to|beside|near|between|from)\s+", phrase)[0].split()[-1])


def _words(phrase: str) -> set[str]:
    return {f for w in re.findall(r"[a-z]+", phrase) for f in (w, singular(w))}


def candidates(instruction: str, scene, unresolved: dict[str, str]) -> tuple[list[Reading], str]:
    """The readings the grounded mentions afford, best first, or none and why."""
    read = mentions(instruction)
    if read is None:
        return [], "negation, a question or repeated words: the rule parser's to read"
    found, actions, goal = read
    if not found:
        return [], "nothing named"
    # every word perception found nothing for is a word of a mention, or one this reading took for a cue (a verb,
    # a goal-state word, a word that frames the request): what another reading could not place is placed here
    tokens = _tokens(instruction)
    placed = set().union(*(_words(m.phrase) for m in found), {tokens[n] for n in _cue_positions(tokens)})
    for phrase, why in unresolved.items():
        if not why.startswith("none"):
            continue
        left = {w for w in re.findall(r"[a-z]+", phrase) if not _closed(w) and w not in _QUANTIFIERS} - placed
        left -= {w for w in left if singular(w) in placed}
        if left and not phrase.endswith((" handle", " knob")):
            return [], f"{phrase!r} not found, and {sorted(left)} is no word of a thing found"
    # every mention grounded: one found nothing is absent, then one several things match is ambiguous
    unseen = [
        m
        for m in found
        if m.phrase not in scene and not ("pour" in actions and _head(m.phrase) in _CONTENTS and m.role == "thing")
    ]  # (contents poured out of the container said with them are out of sight inside it, as planner.py pours)
    for m in sorted(unseen, key=lambda m: unresolved.get(m.phrase, "").startswith("several")):
        why = unresolved.get(m.phrase, "not looked for")
        if why.startswith("several match"):
            return [], (
                f"which {m.phrase!r}? perception found {why.rsplit(' ', 1)[-1]} things that match it and nothing "
                f"in the instruction says which one: name it by where it is or what it looks like"
            )
        return [], f"{m.phrase!r}: {why}"
    distinct: list[Mention] = []
    for m in found:
        same = [
            d for d in distinct if m.phrase in scene and d.phrase in scene and _same(scene[m.phrase], scene[d.phrase])
        ]
        if same and _head(same[0].phrase) != _head(m.phrase):
            # two things said, one thing found: one of them is not there ("the pan" found as the stove)
            return [], f"{same[0].phrase!r} and {m.phrase!r} are the same thing to perception"
        if not same:
            distinct.append(m)  # (contents poured: not seen, a thing of their own)
    out: list[Reading] = []
    fixture_actions = [a for a in actions if a in ("open", "close", "turn_on", "turn_off")]
    moves = [a for a in actions if a in ("put", "stack", "pick", "sort")]
    if fixture_actions and (moves or len(fixture_actions) > 1):
        return [], "a fixture's action and another: several steps, the rule parser's to read"
    others = [a for a in actions if a not in (*fixture_actions, *moves, "pour", "push")]
    if others:
        return [], f"actions {others}: the rule parser's to read"
    dests = [m for m in distinct if m.role == "dest"]
    if "pour" in actions or "push" in actions:
        return _pour_or_push(instruction, distinct, actions, dests), ""
    for a in fixture_actions:
        part = "knob" if a.startswith("turn") else "handle"
        for m in distinct:
            if f"{m.phrase} {part}" in scene or (part == "handle" and "drawer" in m.phrase.split()):
                rest = [x for x in distinct if x is not m]
                if rest:
                    continue
                out.append(Reading(Clause(a, obj=m.phrase, text=instruction), 3.0, f"{a} {m.phrase}"))
    # a sentence that asks to switch or open something asks no carry ("turn the red block on like it's a burner")
    if (moves or goal or dests) and not fixture_actions:
        for o in distinct:
            for t in distinct:
                if o is t:
                    continue
                extra = [x for x in distinct if x is not o and x is not t]
                if any(x.role not in ("source", "near") for x in extra):
                    continue  # a third thing with no part in this reading
                score, why = _score_move(o, t, found, actions, goal)
                if score is None:
                    continue
                source = next((x.phrase for x in extra if x.role == "source"), None)
                action = "stack" if "stack" in actions else "put"
                relation = t.relation or ("in" if _head(t.phrase) in CONTAINERS else "on")
                clause = Clause(
                    action, obj=o.phrase, target=t.phrase, relation=relation, source=source, text=instruction
                )
                out.append(Reading(clause, score, why))
    if "pick" in actions and not dests and len(distinct) == 1 and not fixture_actions:
        m = distinct[0]
        if _head(m.phrase) not in FIXTURES:
            out.append(Reading(Clause("pick", obj=m.phrase, text=instruction), 2.0, f"pick {m.phrase}"))
    out.sort(key=lambda r: -r.score)
    return out, "" if out else "no reading the things afford"


def _pour_or_push(instruction: str, distinct: list[Mention], actions: list[str], dests: list[Mention]) -> list[Reading]:
    """Pour: what is poured (or the container it is in) into the one destination, from the source said. Push: the
    one thing acted on into the one flat area said as its destination."""
    things = [m for m in distinct if m.role == "thing"]
    sources = [m for m in distinct if m.role == "source"]
    if len(dests) != 1 or len(things) > 1 or len(sources) > 1 or len(things) + len(sources) != len(distinct) - 1:
        return []
    if "pour" in actions and not ({"push", "stack", "pick"} & set(actions)):
        if not (things or sources):
            return []  # a pour into the one thing named, with nothing said to pour from: no reading
        obj = (things or sources)[0].phrase
        source = sources[0].phrase if sources else obj
        clause = Clause("pour", obj=obj, target=dests[0].phrase, source=source, text=instruction)
        return [Reading(clause, 3.0, f"pour {obj} into {dests[0].phrase}")]
    ways = {"forward", "forwards", "backward", "backwards", "ahead", "sideways", "left", "right", "toward", "towards"}
    if set(_tokens(instruction)) & (ways | {"leftward", "leftwards", "rightward", "rightwards", "closer", "away"}):
        return []  # which way is said: the rule parser's to read (and to check against where the area is)
    if "push" in actions and things and not sources and set(actions) <= {"push", "put"}:
        target = dests[0].phrase
        if _head(target) in REGIONS or _head(target) in ATTRIBUTES or "area" in target:
            clause = Clause("push", obj=things[0].phrase, target=target, relation="in", text=instruction)
            return [Reading(clause, 3.0, f"push {things[0].phrase} into {target}")]
    return []


def _score_move(o: Mention, t: Mention, found: list[Mention], actions: list[str], goal: bool):
    """How well "put o on/in t" fits the cues; None when it cannot be meant."""
    if t.role in ("source", "near", "tool") or o.role in ("source", "near", "tool"):
        return None, ""
    ho, ht = _head(o.phrase), _head(t.phrase)
    if ho in FIXTURES:
        return None, ""  # a fixture is never carried
    score = 0.0
    why = []
    if t.role == "dest":
        score += 2.0
        why.append(f"{t.phrase!r} after a destination's preposition")
    if o.role == "dest":
        score -= 2.0
    if o.role == "thing":
        score += 1.0
    if ht in SUPPORTS:
        score += 1.0
        why.append(f"{t.phrase!r} holds or supports things")
    if ho in CONTAINERS and ht not in CONTAINERS and ht not in FIXTURES:
        score -= 1.0
    if o.start < t.start:
        score += 0.5
    if not (set(actions) & {"put", "stack", "pick", "sort"}) and not goal and t.role != "dest":
        return None, ""  # nothing says anything is to move
    return score, f"put {o.phrase} on/in {t.phrase}: " + "; ".join(why)


def _same(a, b) -> bool:
    import numpy as np

    return bool(np.allclose(a.position_m, b.position_m, atol=1e-3) and np.allclose(a.extent_m, b.extent_m, atol=1e-3))


def best(instruction: str, scene, unresolved: dict[str, str], effect) -> tuple[list[Reading], str]:
    """The readings to try, best first, when the best wins by `MARGIN` over every reading with another effect
    (`effect(reading) -> hashable`, None when it does not compose); else none and why."""
    readings, why = candidates(instruction, scene, unresolved)
    composed = [(r, effect(r)) for r in readings]
    composed = [(r, e) for r, e in composed if e is not None]
    if not composed:
        return [], why or "no reading composes"
    top, top_effect = composed[0]
    rivals = [r for r, e in composed[1:] if e != top_effect and r.score > top.score - MARGIN]
    if rivals:
        return [], f"{top.why!r} and {rivals[0].why!r} fit about as well"
    return [top], ""
