"""Steps said as a sequence: where one step ends and the next begins, whatever cue says so.

People mark the steps of one instruction in many ways: numbered ("step 1: ... step 2: ...", "1) ... 2) ...", "(a)
... (b) ..."), by sequencing adverbs ("first ..., and finally ...", "next", "lastly", "as a second step", "after
that" with or without a comma), and by a condition that only restates the previous step's result ("open the drawer,
then once it's open put the cheese inside", "find the butter; once you have it, ..."). These are properties of the
sequence, not of any verb or object, so they are read once, here: `sequenced` returns the instruction with each cue
replaced by a sentence boundary, so that the rule parser, the order-free reader and the fallback read each step as a
sentence of its own ("it" in a step still names the thing of the step before: the parser resolves pronouns across
sentences). Nothing is dropped but the cue words: every thing said is still said, so every thing must still be in
the scene."""

from __future__ import annotations

import re

from .rewrite import starts_with_verb

# Where a cue can start: the start of the text, or after a boundary ("," ";" ":" "." a dash) or a conjunction.
_AT = r"(?:^|(?<=[,;:.!?])\s*|\s+-+\s+|\s+(?:and|but)\s+|\s+(?:and\s+)?then,?\s+)"
# A step's number: "step 1:", "step two -", "1)", "(2)", "2.", "#3", "a)" (a letter only with its bracket).
_NUMBER = r"(?:\d|one|two|three|four|five)"
_ENUMERATION = re.compile(
    rf"(?:^|\s+|(?<=[,;.\s]))(?:step\s*{_NUMBER}\s*[:.)-]?|\(?{_NUMBER}\)|\(?[a-e]\)|#\s*{_NUMBER}\s*[:.)-]?|"
    r"(?<![\w.])\d\s*[.:](?=\s+[a-z]))\s*"
)
# A list's header before its steps ("checklist item 4.", "task #2:"): the request's frame, no step.
_HEADER = re.compile(
    r"^(?:(?:checklist|task|job|order|ticket|item|protocol|procedure|exercise)(?: item)? (?:no\.? ?|number |#)?"
    r"(?:\d+|one|two|three|four|five|six|seven|eight|nine|ten)\s*[.:]|"
    # ... or its label alone before a colon ("procedure: 1) ...")
    r"(?:procedure|protocol|steps|instructions|routine|recipe|checklist|sequence)\s*:|"
    # ... or who it is for ("dispatch to unit one:", "note for the robot:", "attention robot:")
    r"(?:(?:dispatch|message|memo|note|orders?|request|instructions?|attention|attn|calling)(?: (?:to|for))? )?"
    r"(?:the )?(?:unit|team|robot|bot|station|arm|crew|operator)(?: (?:\d+|one|two|three|[a-z]))?\s*:|"
    # ... or the bullet of a list's first item ("- pull the drawer open - pick up ...")
    r"[-*\u2022]+(?=\s))\s*"
)
# Sequencing words that can only begin a step ("finally", "as a second step", "after that") ...
_ALWAYS = (
    r"firstly|first of all|first off|to (?:start|begin)(?: with)?|secondly|thirdly|next up|afterwards|after that|"
    r"after this|after which|finally|lastly|last of all|to finish(?: (?:up|off))?|"
    r"as (?:a|the|your) (?:first|second|third|next|final|last) (?:step|thing|move)|"
    r"(?:in|for) (?:the )?(?:first|second|third|next|final|last) (?:step|place)|"
    r"(?:once|when) (?:that(?:'s| is| has been) done|done|finished)"
)
# ... and words that are an ordinal of a thing too ("first bowl", "next to"): a cue only before a comma, an article,
# a pronoun or a verb
_SOMETIMES = r"first|second|third|next"
_CUE = re.compile(rf"{_AT}(?:({_ALWAYS})|({_SOMETIMES}))\b(\s*,)?\s*(?=([a-z(]\S*))")
_STEP_START = frozenset(["the", "a", "an", "it", "them", "this", "that", "these", "those", "you", "i", "we"])
# A condition that only restates what the step before brought about ("once it's open", "once you have it"): the
# sequence already says so.
_AFTER = r"(?:(?<=[.,;:] )|(?<=\bthen ))"
_RESTATED = re.compile(
    rf"{_AFTER}(?:once|when|as soon as|after|now that) (?:it|that|this|they|the \w+(?: \w+)?)"
    r"(?: is| are|'s| has been| have been| was| were) (?:fully |all the way |properly |now )?"
    r"(?:open|opened|closed|shut|out|on|off|done|up|in (?:hand|your (?:hand|gripper)))\s*,?\s+|"
    rf"{_AFTER}(?:once|when|as soon as|after|now that) you(?:'ve| have| are|'re)? "
    r"(?:got|have|grabbed|picked up|holding|taken|got hold of|gotten) (?:it|them|that)(?: up)?\s*,?\s+"
)


def _cue(m: re.Match) -> str:
    if m.group(1) or m.group(3) or m.group(4) in _STEP_START or starts_with_verb(m.group(4)):
        return ". "
    return m.group(0)


def sequenced(text: str) -> str:
    """The instruction (lower case) with its step cues as sentence boundaries ("step 1: pick up the red block. step
    2: ..." -> "pick up the red block. ..."); the text itself when it has none. Only cues that start a step count:
    "the first block", "first bowl from the left" and "next to" name a thing or a place, not a step."""
    out = _HEADER.sub("", text)
    out = _ENUMERATION.sub(". ", out)
    out = _CUE.sub(_cue, out)
    out = _RESTATED.sub("", out)
    if out == text:
        return text
    return re.sub(r"\s*(?:[.,;:]\s*)*\.(?:\s*[.,;:])*\s*", ". ", out).strip(" .")
