"""Learners' and operators' wording said plainly, before the rule parser reads a sentence (round 42, from probe62's
non-native speakers and probe63's operator briefings): "up in air", a learner's word order ("on plate you place
it"), a goal's label for the run ("sorting check: ..."), what a briefing adds that is no step ("..., for the next
run", "..., bring it over, then ..."), and a tool said before the verb ("with it, scrub the plate"). (A learner's
polite frames, "may you", "would you mind to", are fillers in rules/lexicon.py.)

Each rewrite keeps every thing the instruction names (an absent thing is still looked for and refused): only words
that name no thing change, or the word order, or a name said another way ("the wicker tub" is the basket, "the
cabinet roof" its top)."""

from __future__ import annotations

import re


def plain_briefing(text: str) -> str:
    """`text` (lower case, whole instruction) with the wording above said plainly; unchanged when none applies."""
    from .rewrite import starts_with_verb  # (rewrite calls this module: imported when first used)

    # a learner's "up in air", "in your gripper": the air, the gripper
    text = re.sub(r"\b(up |high )?in air\b", r"\1in the air", text)
    text = re.sub(r"\bin (?:your|its|the robot's|robot) gripper\b", "in the gripper", text)
    # "the drawer has to come open": has to be open
    text = re.sub(r"\b(has to|must|should|needs to|need to) come (open|out|off)\b", r"\1 be \2", text)
    # "the block's new home is inside that drawer": where it goes
    text = re.sub(
        r"\b(?:the )?([a-z]+(?: [a-z]+)?)'s new (?:home|place|spot|location) (?:is|will be|should be) "
        r"(?=(?:in|inside|on|onto|on top of|into)\b)",
        r"the \1 goes ",
        text,
    )
    # "sorting check: ...", "drawer test: ...": what the run checks, then the goal
    text = re.sub(
        r"^(?:sorting|stacking|placement|grasp|drawer|stove|pour|scrub|push|lift) (?:check|test)\s*:\s*", "", text
    )
    # "..., all the way down so that it sits flat": how far down a placed thing goes, no step
    text = re.sub(r",?\s*\b(?:all the way|fully|right) (?:down|home)(?= so\b|\s*[,.;!]|\s*$)", "", text)
    # "the cabinet's drawer in the middle", "the drawer at the top": the middle drawer, the top drawer
    text = re.sub(r"\b(drawer|shelf|tier|rack)(s?) (?:in|at) the (middle|top|bottom)\b(?! of\b)", r"\3 \1\2", text)
    # "the black bowl - after you open the top drawer, it goes inside there": the thing said first, then its step
    text = re.sub(
        r"^((?:the|a|an) [a-z][\w ]*?)\s*(?:—|-+|:)\s*(?:after|once) you ([^,]+),\s*(?:it|they) (?:goes|go|belongs|"
        r"should go|needs to go|is going|has to go) (in|inside|into|on|onto|on top of) (?:there|it)\b",
        r"\2, then put \1 \3 it",
        text,
    )
    # a learner's order: "on plate you place it" -> "place it on the plate"
    text = re.sub(
        r"(^|,\s*(?:and )?|\b(?:and|then) )(on|in|into|onto|inside) (?:the )?([a-z]+(?: [a-z]+)?) you (?:then )?"
        r"(place|put|set|drop|lay|stand) (it|them)\b",
        r"\1\4 \5 \2 the \3",
        text,
    )
    # "near the plate you see one black bowl": there is one there
    text = re.sub(
        r"(^|[.;!]\s*)(near|by|next to|beside|behind|in front of|on) the ([a-z]+(?: [a-z]+)?) you (?:can |will |'ll )?"
        r"(?:see|find|notice|have) (?:one|a|an|the) ([a-z]+(?: [a-z]+)?)(?=\s*[.;,!])",
        r"\1there is a \4 \2 the \3",
        text,
    )
    # "take it ..., bring it over, then set it on the plate": carrying it there is no step of its own
    text = re.sub(
        r",\s*(?:and )?(?:bring|carry|take) (?:it|them) (?:over|across)(?: here| there)?\s*,\s*(?:and )?(?:then )?",
        ", then ",
        text,
    )
    # "the cabinet roof": its top
    text = re.sub(r"\bthe ([a-z]+)(?:'s)? roof\b", r"the top of the \1", text)
    # "..., for this one", "... for the next run": which run it is for, no part of the goal
    text = re.sub(
        r",?\s*\bfor (?:this|the next|the|this next|today's) (?:one|run|trial|task|episode|round|scene|test)\b",
        "",
        text,
    )
    # "the middle drawer is the one i need open", "the lowest drawer is the one to open": the request
    text = re.sub(
        r"^((?:the )?[a-z' ]+?) is the one (?:(?:i|we) (?:need|want|would like|'d like)(?: to be)? |to (?:be )?)"
        r"(open|opened|closed|shut|close)\b",
        lambda m: f"{'open' if m.group(2).startswith('open') else 'close'} {m.group(1)}",
        text,
    )
    # "wine bottle up on top of the cabinet", "red block up on the plate": a goal said without a verb (the noun
    # and the particle are no phrasal verb, "bottle up")
    text = re.sub(
        r"(^|[.;!]\s+)((?:the |a )?[a-z]+(?: [a-z]+)?) (?:up|down|over) "
        r"(?=(?:on|onto|into|inside|on top of)\b|in\b(?! the (?:air|gripper|hand|fingers)\b))",
        lambda m: m.group(0) if starts_with_verb(m.group(2)) else f"{m.group(1)}{m.group(2)} ",
        text,
    )
    # "the wicker tub", "the wicker carrier": a basket (what is woven of wicker here)
    text = re.sub(r"\bwicker (?:tub|carrier|box|bin|container|holder|hamper|thing|one)\b", "wicker basket", text)
    # "...; that's this run's target": the goal's own name, said as a sentence after it
    text = re.sub(
        r"(?<=[.;!])\s*(?:that|this)(?:'s| is) (?:the |my |our |this (?:scene|run|task|trial)'s )"
        r"(?:target|goal|point|aim|idea|plan|deliverable|end state|target state|final state)\b[^.;!]*[.!]?\s*$",
        "",
        text,
    )
    # "lift it straight up": up
    text = re.sub(r"\bstraight (up|upward|upwards)\b", r"\1", text)
    # "a single drawer", "just the one drawer": one drawer
    text = re.sub(r"\b(?:a|one|the) (?:single|sole|lone) (?=[a-z])", "a ", text)
    # "lying just before the square": in front of it (a learner's "before" of a place)
    text = re.sub(
        r"\b(lying|sitting|standing|resting|placed|located|positioned|parked|set|sat) (?:just |right |directly )?"
        r"before (?=the\b)",
        r"\1 in front of ",
        text,
    )
    # "on the right half of the table", "over on the left side of the table": on the right, on the left
    text = re.sub(
        r"\b(?:over )?on the (left|right|far left|far right)(?:-hand| hand)? (?:half|side|part|end) of the "
        r"(?:table|counter|workspace|tabletop|bench)\b",
        r"on the \1",
        text,
    )
    # "the drawer pulled out, open": the same state said twice
    text = re.sub(r"\b(?:pulled|slid|drawn) (?:out|open),? (?:and )?(open|opened)\b", r"\1", text)
    # "red block in the green square, pushed there rather than carried", "... (pushed forward, not carried)": a
    # push
    text = re.sub(
        r"^((?:the |a )?[a-z][\w ]*? (?:in|into|inside|onto|on|to|->) (?!be\b)(?:the )?[\w ]+?),? "
        r"(?:pushed|slid|shoved|nudged) "
        r"(?:there|in|in there|into it|forward|forwards|along|across|over)\b"
        r"(?:,? (?:rather than|instead of|and not|not|never|but not) (?:carried|lifted|picked up))?",
        r"push \1",
        text,
    )
    # "up in the air, in the gripper": where a lifted thing is, said twice
    text = re.sub(
        r"\b((?:up )?in the air|(?:up )?in the gripper|up off the table)\s*,\s*(?:held )?(?:up )?in the "
        r"(?:gripper|hand|fingers|air)\b",
        r"\1",
        text,
    )
    # "with it, scrub the plate": the tool said first, as after the verb
    text = re.sub(
        r"(^|[.;!]\s+)(with|using) (it|them|that|this|(?:the|that|this) [a-z]+(?: [a-z]+)?),\s*"
        r"((?:scrub|wipe|clean|rub|polish|push|shove|nudge|poke|sweep)\b[^.;!]*)",
        r"\1\4 \2 \3",
        text,
    )
    return text
