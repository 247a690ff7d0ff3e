"""An instruction of several steps read one step at a time.

When the whole instruction reads in no way the planner knows (rule parse, order-free reader, the scene-afforded
reading), a wording of one step can still be one that only another reading knows ("grab the red block. then it
should end up sitting on the plate": the first step parses, the second is a goal only the fallback reads). `steps`
cuts the instruction into its steps (sentences, and clauses with a verb or a destination of their own) and says
each on its own: a pronoun that begins a step's object ("it", "them", "that one") is the thing the step before
acted on, named again. The planner plans each step with its whole pipeline and joins them (planner.py); every
check applies to each step, so a step that names a thing perception did not find, or names nothing, refuses the
whole. Text only (no scene), so that observe looks for exactly the phrases the planner will need."""

from __future__ import annotations

import re

from .parse import ParseError, is_pronoun, parse_instruction
from .things import is_thing

_PRONOUN = re.compile(r"\b(?:it|them|that one|this one)\b")
# Where one step ends and the next begins, in the instruction's own words: a sentence's end, or a sequencing word
# after a comma or "and" (rules/steps.py has made every other cue a sentence's end).
_BOUNDARY = re.compile(
    r"\s*[.;!?]+\s+(?:(?:and\s+)?then,?\s+)?|\s*,?\s+(?:and\s+)?then,?\s+|\s*,\s*(?:and\s+)?after that,?\s+"
)
_NAMED = re.compile(r"\b(?:the|a|an) ([a-z]+(?: [a-z]+){0,2})")


def steps(instruction: str) -> list[str]:
    """Each step of the instruction said on its own, pronouns bound to the step before's thing; [] for fewer than
    two steps or when a pronoun has nothing to stand for."""
    parts = [p.strip(" ,.") for p in _BOUNDARY.split(instruction.strip().lower()) if p.strip(" ,.")]
    if len(parts) < 2:
        return []
    out: list[str] = []
    thing: str | None = None
    for part in parts:
        said = _PRONOUN.search(part)
        # only a pronoun said before the step names a thing of its own ("grab the pear and drop it in": the pear)
        if said and not any(_thing_of(w) for w in _NAMED.findall(part[: said.start()])):
            if thing is None:
                return []
            part = _PRONOUN.sub(f"the {thing}", part, count=1)
        out.append(part)
        thing = _acted_on(part) or thing
    return out


def _acted_on(step: str) -> str | None:
    """The thing a step acts on, as the rule parse reads it (its last clause's object), or else the last thing it
    names ("the blue block stays put")."""
    try:
        clauses = parse_instruction(step)
    except ParseError:
        named = [_thing_of(words) for words in _NAMED.findall(step)]
        return next((n for n in reversed(named) if n), None)
    return next((c.obj for c in reversed(clauses) if c.obj and not is_pronoun(c.obj)), None)


def _thing_of(words: str) -> str | None:
    """ "blue block stays put" -> "blue block": the words after an article up to the last that names a thing."""
    said = words.split()
    ends = [i for i, w in enumerate(said) if is_thing(w)]
    return " ".join(said[: ends[-1] + 1]) if ends else None
