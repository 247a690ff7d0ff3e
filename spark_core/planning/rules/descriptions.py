"""Descriptions: sentences that say how the scene or the session is, said around the request ("there's a green block
sitting out on the right and the wicker basket is closer in on the left. end result i'm after: green block inside
the basket", "the plate's a bit grubby. scrub the plate with the sponge", "this is the pushing test. push the red
block forward ..."). When every reading of the whole refuses, the planner reads the other sentences without them
(planner._without_remarks): a description asks nothing (no verb first, no wish, duty or goal word, no question to
the robot) and names no kind of thing the scene lacks, so an absent thing is still refused."""

from __future__ import annotations

import re

from .remarks import names_absent
from .rewrite import starts_with_verb

# What a sentence that asks says: a wish, a duty, where a thing goes, a request to the robot, a label for the goal.
_ASKS = re.compile(
    r"\b(?:please|pls|should|must|need|needs|needed|has to|have to|had better|got to|gotta|ought|want|wants|wanted|"
    r"like|love|prefer|hoping|hope|after|goes|go|belongs?|end(?:s|ed)? up|ends|finish(?:es)? up|could|can|would|will|"
    r"let's|let|make sure|ensure|mind|try|leave|keep|then|first|next)\b|[:>=\u2192]"
)
# How a description starts: a thing said to be there, the speaker or the session, or a thing and how it is.
_DESCRIBES = re.compile(
    r"^(?:(?:there|here)(?:'s| is| are| was| were)\b|"
    r"(?:we|i|this(?: one)?|that(?: one)?|someone|somebody|it|they|you)"
    r"(?:'re|'m|'s|'ve| am| are| is| was| were| have| had| set| left| put| keep| keeps)\b|"
    r"(?:the|a|an|my|our|this|that|those|these|both|two|three) [a-z' -]+?(?:'s| is| are| was| were| has| have| sits|"
    r" rests| lies| stands| looks| seems)\b)"
)

# A sentence that says what does not matter ("i don't really care how you get there", "doesn't matter which way
# up"): it leaves the way open and asks nothing.
_INDIFFERENT = re.compile(
    r"^(?:(?:i|we) (?:do not|don't|dont) (?:really |much |particularly |honestly )?(?:care|mind)|"
    r"(?:it |that )?(?:does not|doesn't|doesnt) (?:really |much )?matter|(?:either|any|whatever) (?:way|order) "
    r"(?:is|'s) (?:fine|ok|okay))\b"
)

# A sentence that names the session's task with no verb ("just a placement test this time, nothing fancy.", "little
# warm-up task before the real stuff.", "bit of a strange one today."): a label for the run, not a request.
_SESSION = re.compile(
    r"^(?:(?:just|only|another|a|an|the|this|our|my|bit of a|one more|quick|little|simple|easy)\s+)*"
    r"(?:[a-z-]+\s+){0,2}?(?:(?:test|task|run|check|job|trial|exercise|warm-up|warmup|round|demo|session)s?|"
    r"(?:easy|simple|quick|strange|odd|tricky|last|first|next|final) one)\b[^.!?:]*[.!]?$"
)


def descriptions(instruction: str, found: list[str] | None) -> tuple[str, list[str]]:
    """The instruction without the sentences that only describe, and those sentences; the instruction and no
    sentences when none describes, every sentence does, or one names a thing the scene lacks (`found`: perception's
    phrases and the scene's inventory; None before perception looked, to know what to look for)."""
    # a description in brackets ("... in the white bowl (the bowl's the round one over on your left).")
    bracketed = [m for m in re.finditer(r"\s*\(([^()]*)\)", instruction) if _describes(m.group(1))]
    text = instruction
    for m in reversed(bracketed):
        text = text[: m.start()] + text[m.end() :]
    said = [t.strip() for t in re.split(r"(?<=[.!?;])\s+", text.strip()) if t.strip()]
    aside = [m.group(1).strip() for m in bracketed] + [t for t in said if _describes(t)]
    kept = [t for t in said if not _describes(t)]
    if not aside or not kept or (found is not None and any(names_absent(_mine(t), found) for t in aside)):
        return instruction, []
    return " ".join(kept), aside


def _describes(sentence: str) -> bool:
    """The sentence says how things are, and asks nothing."""
    text = sentence.lower().replace("\u2019", "'").strip()
    text = re.sub(r"^(?:(?:ok|okay|so|right|alright|well|now|and|oh|um|uh),?\s+)+", "", text)
    if text.endswith("?") or starts_with_verb(text):
        return False
    if _INDIFFERENT.match(text) or (_SESSION.match(text) and not _ASKS.search(text)):
        return True
    return bool(_DESCRIBES.match(text)) and not _ASKS.search(text)


def _mine(sentence: str) -> str:
    """The description without what the speaker says is theirs ("it keeps catching my sleeve", "our notes say
    ..."): the speaker's own things are not on the table, so they are no thing the scene lacks."""
    return re.sub(r"\b(?:my|our) (?:own )?[a-z]+(?:'s)?\b", "", sentence, flags=re.IGNORECASE)
