"""Words around a goal that say it again or hedge it, and terse forms of it ("that drawer shut, all the way in",
"the sponge - the yellow one", "red block on the plate, sitting flat, ideally near the middle", "plate: scrubbed,
sponge as the tool", "the red block up in the gripper, clear of the table"): said plainly, so the parser reads one
step per goal. Each rewrite keeps to its own clause, so a second clause that contradicts the first is left for the
contradiction check ("close the drawer but leave it fully open")."""

from __future__ import annotations

import re

from ...perception.colors import BASE_COLOURS

_PLACES = "left|right|middle|centre|center|front|back|rear|side|end|top|bottom|table|corner|edge|far|near"
_LOOKS = "|".join(sorted(BASE_COLOURS) + ["big", "small", "little", "large", "tall", "short", "wooden", "metal"])


def restated(text: str) -> str:
    """`text` (lower case) without the words that restate or hedge its goal, its terse forms said in full."""
    # "that drawer shut, all the way in": how far it goes says the same state again
    text = re.sub(
        # (the thing at most three words, no second clause: "close the drawer but leave it fully open" is kept)
        r"\b(shut|closed|close|open|opened)((?: (?:the|that|this|its|it)\b(?: (?!(?:but|and|while|then|leave|keep|"
        r"keeping|yet|though)\b)[a-z]+){0,2})?),? "
        r"(?:all the way|fully|completely)(?: (?:in|out|home|back|closed|shut|open))?(?=\s*(?:[.,;!]|$))",
        r"\1\2",
        text,
    )
    # "..., there's only the one sponge out": a note that one thing of its kind is there, no step
    text = re.sub(
        r"\s*[,;-]\s*(?:there(?:'s| is) (?:only|just) (?:the )?one [a-z]+|(?:it's|it is|that's|that is) the only "
        r"[a-z]+)(?: out| here| there| around| on the table| in the scene| left)?(?=\s*(?:[.;!]|$))",
        "",
        text,
    )
    # "the sponge - the yellow one": a colour or size said after the thing, as an apposition, is the thing's own
    text = re.sub(
        # (a thing's name, not a place: "the pear on the left - the yellow one" is read elsewhere)
        rf"\bthe (?!(?:{_PLACES})\b)([a-z]+)\s*[,-]+\s*the ({_LOOKS}) one\b(?=\s*(?:[.;!]|$))",
        r"the \2 \1",
        text,
    )
    # "red block on the plate, sitting flat, ideally somewhere near the middle": how it sits and a hedged wish of
    # where on it, said after the goal, are no step of their own
    text = re.sub(
        r",\s*(?:sitting|lying|standing|resting|set) (?:flat|upright|level|straight|square)(?=\s*(?:[.,;!]|$))",
        "",
        text,
    )
    # "..., if you can, then ...": a courtesy between two steps, no step of its own
    text = re.sub(r",\s*(?:if (?:you can|you could|possible|you don't mind)|please)\s*(?=,)", "", text)
    text = re.sub(r",\s*(?:ideally|preferably)\b[^.;!?,]*(?=[.;!?]|$|,\s*(?:then|and)\b)", "", text)
    # "the hamper, the woven brown one over on the left": after the thing's name, what it looks like is said again;
    # where it is picks it out ("the hamper, the one on the left")
    text = re.sub(
        r"(\bthe (?:[a-z]+ ){0,2}[a-z]+\s*(?:,|\s-+)\s*the) (?:[a-z]+ ){1,3}?(?:one|thing)"
        r"(?: (?:over|out|way out|just|sitting|set))? "
        r"(?=(?:on|to|at) the (?:left|right|back|front|far|near)\b)",
        r"\1 one ",
        text,
    )
    # "plate: scrubbed, sponge as the tool": the tool said as what it serves as, the state after the thing's label
    text = re.sub(
        r"\b(?:using |with )?((?:the |a )?[a-z]+) as (?:the |a |my )?(?:tool|scrubber|implement)\b", r"with \1", text
    )
    text = re.sub(
        r"^(?:the )?([a-z]+(?: [a-z]+)?)\s*:\s*(?:scrubbed|wiped|cleaned|scoured)\b,?\s*", r"scrub the \1 ", text
    )
    # "turn the stove knob so the burner comes on": the sense of the turn, said as what it makes happen
    text = re.sub(
        r"^(turn|twist|rotate|switch) ((?:the )?[a-z ]+?),? so (?:that )?(?:the [a-z ]+?|it) (?:comes|goes|turns|is|"
        r"gets|switches)(?: back)? (on|off)\b",
        r"turn \3 \2",
        text,
    )
    # "the black bowl tucked in the top drawer": where it sits
    text = re.sub(r"\btucked (?=(?:away )?(?:in|inside|into|under|behind)\b)", "sitting ", text)
    text = re.sub(r"\bsitting away (?=in)", "sitting ", text)
    # "black bowl by ramekin, onto plate": a destination said after a comma without its article
    text = re.sub(
        r"([,:]\s*(?:onto|into|on top of)) (?!(?:the|a|an|it|them|there|here|this|that|these|those|its|their|my|your|"
        r"one|each|both|either)\b)(?=[a-z]+\s*(?:[.,;!]|$))",
        r"\1 the ",
        text,
    )
    # "...; done": the end of the list, no step
    text = re.sub(r"\s*[;,.]\s*(?:done|that's it|that's all|end|finished)\s*[.!]?$", "", text)
    # "up in the gripper, clear of the table": the second phrase says again that the thing is lifted
    text = re.sub(
        r"\b((?:up )?in the (?:gripper|air|hand)|lifted|raised|held up),? (?:and )?(?:well )?(?:clear of|off|above|"
        r"away from) the (?:table|surface|tabletop|ground)\b",
        r"\1",
        text,
    )
    # "the red block in the gripper": a thing said to be in the robot's hand, with no verb, is lifted
    text = re.sub(r"^((?:the|a|an) [a-z ]+?) (?:up )?in the (?:robot's )?(?:gripper|hand)(?=[.!,]|$)", r"lift \1", text)
    # "the red block clear of the table": a thing said to be off what it stood on, with no verb, is lifted
    text = re.sub(
        r"^((?:the|a|an) [a-z ]+?) (?:up )?(?:well )?(?:clear of|off) the (?:table|surface|tabletop)(?=[.!]?$)",
        r"lift \1",
        text,
    )
    return text
