"""Instruction -> clauses (action, object phrase, target phrase, tool, direction), with what was understood."""

from __future__ import annotations

import re
from dataclasses import dataclass, field

from .lexicon import DETERMINERS, DIRECTIONS, FILLERS, FROM, IN, ON, PARTICLE_VERBS, PRONOUNS, VERBS, WITH


class ParseError(ValueError):
    """The instruction could not be understood; the message says what was and what was not."""


@dataclass(frozen=True)
class Clause:
    action: str  # a key of lexicon.VERBS
    obj: str | None = None  # object phrase (determiners stripped), or a pronoun
    target: str | None = None  # where it goes / what is poured into / what is scrubbed
    relation: str | None = None  # on | in (for put/stack/push into)
    tool: str | None = None  # scrub with
    source: str | None = None  # pour from
    direction: str | None = None  # forward | backward | left | right
    distance_m: float | None = None
    text: str = field(default="", compare=False)


def normalise(text: str) -> str:
    text = text.lower().strip()
    text = re.sub(r"[!?.;:]+", " , ", text)
    text = re.sub(r"\s+", " ", text)
    text = text.replace("next to", "next_to")  # a relation, not the filler "next"
    for f in sorted(FILLERS, key=len, reverse=True):
        text = re.sub(rf"(^|\s|,){re.escape(f)}(\s|,|$)", r"\1 \2", text)
    text = text.replace("next_to", "next to")
    text = re.sub(r"\s+", " ", text).strip(" ,")
    # "use the sponge to scrub the plate" -> "scrub the plate with the sponge"
    return re.sub(r"^(?:use|take) (.+?) (?:to|and) (\w+) (.+)$", r"\2 \3 with \1", text)


def noun_phrase(words: str) -> str:
    """Strip determiners and tidy "drawer of the cabinet" -> "cabinet drawer"."""
    ws = [w for w in words.replace(",", " ").split() if w not in DETERMINERS]
    text = " ".join(ws).strip()
    m = re.fullmatch(r"(.+?) (?:of|on|from) (.+)", text)
    if m and m.group(2).split()[-1] not in ("stove", "table") or m and "drawer" in m.group(1):
        text = f"{m.group(2)} {m.group(1)}"
    return text


def object_phrase(words: str) -> str:
    """An object phrase that may locate the object by another ("bowl next to the plate"): determiners go, the
    relation stays in place (noun_phrase's "drawer of the cabinet" reordering would scramble it)."""
    if re.search(r"\b(between|next to|beside|near|on top of|on|in|inside|at|from)\b", words):
        return " ".join(w for w in words.replace(",", " ").split() if w not in DETERMINERS)
    return noun_phrase(words)


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
    m = re.fullmatch(r"(?:turn|switch) (.+) (on|off)", clause)  # "turn the stove on"
    if m:
        return ("turn_on" if m.group(2) == "on" else "turn_off"), m.group(1)
    best = None
    for action, forms in VERBS.items():
        for f in forms:
            if (clause == f or clause.startswith(f + " ")) and (best is None or len(f) > len(best[2])):
                best = (action, clause[len(f) :].strip(), f)
    return (best[0], best[1]) if best else None


def split_clauses(text: str) -> list[str]:
    parts = re.split(
        r"\s*,\s*(?:and\s+)?(?:then\s+)?|\s+(?:and\s+)?then\s+|\s+and\s+(?=(?:"
        + "|".join(re.escape(f) for forms in VERBS.values() for f in forms)
        + r")\b)|\s+after that\s+|\s+before\s+",
        text,
    )
    return [p.strip() for p in parts if p and p.strip()]


def parse_instruction(instruction: str) -> list[Clause]:
    text = normalise(instruction)
    if not text:
        raise ParseError("the instruction is empty")
    clauses: list[Clause] = []
    raw = split_clauses(text)
    # "put A in B and C in D": a second object/target pair after "and" with no verb of its own
    expanded: list[str] = []
    for part in raw:
        # ("between the plate and the ramekin" is one phrase)
        expanded += (
            [p for p in re.split(r"\s+and\s+(?=(?:the|a|an)\s)", part) if p.strip()]
            if " between " not in f" {part} "
            else [part]
        )
    previous: str | None = None
    for part in expanded:
        verb = _match_verb(part)
        if verb is None:
            if previous is None:
                known = ", ".join(sorted({f for forms in VERBS.values() for f in forms[:2]}))
                raise ParseError(f"no action I know in {part!r}; I understand verbs such as {known}")
            action, rest = previous, part  # ellipsis: "..., then the red block on the green block"
        else:
            action, rest = verb
        previous = action
        clauses.append(_clause(action, rest, part))
    return clauses


def _clause(action: str, rest: str, text: str) -> Clause:
    particle = PARTICLE_VERBS.get(action)
    if particle and rest.endswith(" " + particle):
        rest = rest[: -len(particle) - 1]
    if action == "pick" and rest.startswith("up "):
        rest = rest[3:]
    distance, rest = _distance(rest)
    direction, rest = _direction(rest)
    if action == "scrub":
        split = _split_on(rest, WITH)
        obj, tool = split if split else (rest, None)
        off = _split_on(obj, ("off of", "off", "from"))
        obj = re.sub(r"\s+clean$", "", off[0] if off else obj)  # "wipe the dirt off the table": the dirt goes
        return Clause(action, target=noun_phrase(obj), tool=noun_phrase(tool) if tool else None, text=text)
    if action == "pour":
        into = _split_on(rest, IN) or _split_on(rest, ON)
        what, target = into if into else (rest, None)
        src = _split_on(what, FROM)
        obj, source = src if src else (what, None)
        source = noun_phrase(source) if source else noun_phrase(obj)
        return Clause(
            action,
            obj=noun_phrase(obj) if obj else None,
            target=noun_phrase(target) if target else None,
            source=source,
            text=text,
        )
    if action == "pick":  # "pick the bowl on the stove": where it is picks out which bowl; keep it in the phrase
        return Clause(action, obj=object_phrase(rest) or None, direction=direction, distance_m=distance, text=text)
    for relation, preps in (("in", IN), ("on", ON)):
        split = _split_on(rest, preps)
        if split:
            obj, target = split
            return Clause(
                action,
                obj=noun_phrase(obj) or None,
                target=noun_phrase(target) or None,
                relation=relation,
                direction=direction,
                distance_m=distance,
                text=text,
            )
    split = _split_on(rest, ("to the front of", "next to", "to", "toward", "towards", "beside"))
    if split and action in ("put", "push"):
        obj, target = split
        return Clause(
            action,
            obj=noun_phrase(obj),
            target=noun_phrase(target),
            relation="near",
            direction=direction,
            distance_m=distance,
            text=text,
        )
    return Clause(action, obj=noun_phrase(rest) or None, direction=direction, distance_m=distance, text=text)


def is_pronoun(phrase: str | None) -> bool:
    return phrase is not None and phrase in PRONOUNS
