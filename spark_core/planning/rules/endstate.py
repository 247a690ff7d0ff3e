"""The request written as a specification of the end state, as evaluation prompts word it: "the final configuration
should have the red cube resting atop the green cube", "success is defined as the juice carton resting in the
basket", "the objective is for the sauce to be located inside the basket", "the final configuration should be a
three-block tower with the blue block at its base, the green block in the middle and the red block at the top".

The frame names no thing and asks nothing: what it frames is the state to reach, said as "X should be ...", which the
parser reads as a goal. With it, the formal words such specifications use for ordinary ones ("situated", "upon",
"within", "has been deposited")."""

from __future__ import annotations

import re

from .restated import restated

# "the final configuration should have ...", "the desired end state is one in which ...", "the end state: ..."
_FRAME = re.compile(
    r"^(?:the |a |an |our |my |your )?(?:(?:final|end|desired|target|goal|resulting|intended|expected|ideal|required)"
    r"(?: end| final)? )(?:configuration|config|state|arrangement|layout|set-?up|scene|result|outcome|condition|"
    r"situation|picture)s?\s*"
    r"(?::|=|-+>?|(?:(?:should|must|will|shall|needs to|has to|ought to|is to) )?(?:be )?"
    r"(?:have|has|show|shows|feature|features|contain|contains|include|includes|consist of|consists of|"
    r"(?:(?:is|be) )?one (?:in which|where|with)|(?:is|be) (?:that|where|with)|is|be|reads?))\s*(?:that )?(?=\S)"
)
# "success is defined as ...", "success means ...", "the objective is for ... to be ...", "the goal is that ..."
_AIM = re.compile(
    r"^(?:(?:task )?success (?:is defined as|is defined by|means|=|:|is when|is)|"
    r"(?:the |my |our |your )?(?:objective|goal|aim|target|intention|idea|point) (?:here )?is (?:for|that|having))"
    r"\s+(?=\S)"
)
# said before or after the state, of the run rather than of any thing
_WHEN = re.compile(
    r"^(?:(?:following|after|upon|on|at the end of|by the end of) (?:the )?(?:execution|completion|the run|the task|"
    r"the episode|the trial|execution of the task)|at the end|in the end|by the end|at the finish)\s*,?\s*"
)
_WHEN_AFTER = re.compile(
    r",?\s*(?:once|when|after|by the time) (?:the )?(?:task|run|episode|trial|execution|robot|arm|you|it) "
    r"(?:is |are |'re |has |have |'s )?(?:complete|completed|finished|done|over|ended)\b"
)
# a question whose answer is the request ("is it possible that the bowl ends up on the plate? that is my wish")
_POSSIBLE = re.compile(
    r"^(?:is it possible|would it be possible|could it be|can it be|any chance) (?:that|for) (.+?)\s*\?"
    r"(?:\s*(?:that|this)(?:'s| is) (?:my|our|the) (?:wish|goal|hope|dream|plan|request|aim)\b\W*)?\s*$"
)
# the verb-less state of one thing: "the red cube resting atop the green cube" -> "... should be on top of ..."
_PARTICIPLES = (
    r"(?:resting|sitting|standing|lying|located|situated|placed|positioned|deposited|kept|stored|perched|set)"
)


# "the beads in the mug are to be poured into the bowl": a request said in the passive; the verb each participle is of
_PASSIVE = {"poured": "pour", "placed": "place", "put": "put", "moved": "move", "transferred": "transfer", "set": "set"}
_PASSIVE |= {"stacked": "stack", "pushed": "push", "opened": "open", "lifted": "lift", "relocated": "move"}
_PASSIVE |= {"deposited": "put", "positioned": "put", "wiped": "wipe", "scrubbed": "scrub", "emptied": "empty"}


def _passive(text: str) -> str:
    """ "the beads resting inside the red mug are to be poured into the bowl" -> "pour the beads resting inside the
    red mug into the bowl": the thing a passive request is said of is what the verb acts on."""
    m = re.match(
        r"((?:the|a|an) [a-z' -]+?) (?:is|are|should|must|needs to|need to|has to|have to|ought to) (?:to )?be "
        rf"({'|'.join(_PASSIVE)})\b(?! (?:position|state)\b)(.*)",
        text,
    )
    return f"{_PASSIVE[m.group(2)]} {m.group(1)}{m.group(3)}" if m else text


def formal_words(text: str) -> str:
    """The plain word for a formal one: "situated" -> "located", "atop" -> "on top of", "upon" -> "on", "within" ->
    "in" (not "within reach"), "is to be found" / "has been deposited" -> "should be", "presently held in" -> "in"."""
    # "(seed 0)": which run of the scene, nothing to act on
    text = re.sub(r"\s*\(\s*seed\s*#?\s*\d+\s*\)|,?\s*\bseed\s*#?\s*\d+\s*$", "", text)
    text = re.sub(r"\bsituated\b", "located", text)
    text = re.sub(r"\blocated (?=(?:farther|further|closer|nearer|farthest|furthest|closest|nearest)\b)", "", text)
    # "..., such that its burner is active": the state just asked for, said again of its part
    text = re.sub(
        r",? (?:such|so) that (?:its|the) [a-z ]+? (?:is|are|becomes?) (?:active|hot|lit|on|running|heating|working|"
        r"engaged)\b",
        "",
        text,
    )
    # "rotate the stove's knob to the on position": switching it on
    text = re.sub(
        r"\b(?:rotate|turn|twist|set|switch|move|flip) ((?:the|a|an) [a-z' ]+?) (?:to|into) (?:the |its )?(on|off) "
        r"(?:position|setting|state)\b",
        r"turn \2 \1",
        text,
    )
    # "open the drawer by means of its metal handle": how, by a part of the thing itself
    text = re.sub(r",? (?:by means of|by way of|using|via|by) (?:its|the) (?:[a-z]+ )?handle\b", "", text)
    # "on top of the drawers": the chest they make, the cabinet
    text = re.sub(r"\btop of the drawers\b", "top of the cabinet", text)
    # "take the bottom cube out and put it on ...": out of where it is, a pick
    text = re.sub(r"\b(take|get|lift) ((?:the|a|an) [a-z ]+?) out\b(?! of)", r"\1 \2", text)
    # "the plate's neighbour bowl": the bowl next to the plate
    text = re.sub(r"\bthe ([a-z]+)'s (?:neighbou?r|neighbou?ring|adjacent) ([a-z]+)\b", r"the \2 next to the \1", text)
    text = re.sub(r"\b(i|we) (?:want|would like|'d like|wish|need|hope) to see\b", r"\1 want", text)
    # "the rightmost of the grocery items, namely the cream cheese,": the thing said precisely is the thing
    text = re.sub(
        r"\b(?:the|a|an) [a-z' ]+?,? (?:namely|i\.e\.?|specifically|to be precise|to be exact|viz\.?),? "
        r"((?:the|a|an) [a-z' ]+?)(?:,|(?= (?:into|onto|in|on|to|inside)\b)|(?=\s*[.!]?$))",
        r"\1",
        text,
    )
    # "... rather than the one on the cabinet", "... rather than inside any of its drawers": a thing or place ruled out
    text = re.sub(
        r",? rather than (?=(?:the|that|this) (?:one|[a-z]+)\b|(?:in|inside|into|on|onto) (?:any|one|a|an|the)\b)",
        ", not ",
        text,
    )
    # "so its on target": a purpose said with its apostrophe dropped ("so its lid ..." keeps its possessive)
    text = re.sub(
        r"\bso its (?=(?:on|off|in|out|not|clear|ready|easy|there|where|safe|visible|upright|away)\b)", "so it's ", text
    )
    # "the drawer should be left in an open position": the state it is left in
    text = re.sub(
        r"\b(?:is|are|should|must|needs to|has to) (?:to )?be left (?:in |at )?(?:an |the |its )?"
        r"(open|opened|closed|shut)"
        r"(?: position| state)?\b",
        r"should be \1",
        text,
    )
    text = re.sub(r"\batop\b", "on top of", text)
    # "the beads resting inside the mug": where they are, not where they go ("inside" is no destination here)
    text = re.sub(r"\b(resting|sitting|lying|kept|held|located) inside\b", r"\1 in", text)
    # "whichever black bowl lies farthest to the right": the rightmost black bowl
    text = re.sub(
        r"\bwhichever ((?:[a-z]+ )?[a-z]+) (?:lies|sits|stands|rests) (?:the )?(farthest|furthest|nearest|closest|"
        r"leftmost|rightmost|highest|lowest)(?: (?:to|on) the (left|right)\b)?",
        lambda m: f"the {m.group(3)}most {m.group(1)}" if m.group(3) else f"the {m.group(2)} {m.group(1)}",
        text,
    )
    # "the beads resting in the red mug": the contents of the mug
    text = re.sub(
        r"\b(beads|contents|marbles|balls) (?:resting|sitting|lying|kept|held|located) (?=(?:in|inside)\b)",
        r"\1 ",
        text,
    )
    # "the basket located on the left-hand side", "the mug, located on the right, into ...": where it is, a side
    text = re.sub(
        r",?\s*\b(?:located|positioned|placed|sitting|standing|lying|set) ((?:on|to|at) (?:the|your) (?:far )?"
        r"(?:left|right)(?:-hand| hand)?(?: side)?)\s*,?(?=\s|$|[.!])",
        r" \1",
        text,
    )
    text = re.sub(r"\bupon\b", "on", text)
    text = re.sub(r"\b(?:employ|utili[sz]e|make use of)(?= (?:the|a|an)\b)", "use", text)
    text = re.sub(r"\bwithin\b(?! (?:reach|range|the robot's reach|arm's reach))", "in", text)
    text = re.sub(r"\b(?:(?:presently|currently|now) )?held (?=(?:in|inside|by)\b)", "", text)
    text = restated(text)
    text = re.sub(r"\b(?:is|are) to be found\b|\bshould be found\b", "should be", text)
    # "place on the plate the black bowl in the top drawer, not the one ...": the destination said before the thing
    text = re.sub(
        r"^((?:please )?(?:put|place|set|move|transfer|deposit|bring|carry|relocate)) "
        r"(on|onto|in|into|to|inside|on top "
        r"of) ((?:the|a|an) [a-z ]+?),? ((?:the|a|an|whichever|which ever) [^,.!]+?)([,.!].*)?$",
        lambda m: f"{m.group(1)} {m.group(4)} {m.group(2)} {m.group(3)}{m.group(5) or ''}",
        text,
    )
    return re.sub(
        r"\b(?:has|have) been (?:deposited|placed|put|set|positioned|moved|transferred|stowed|stored|relocated) "
        r"(?=(?:in|inside|into|on|onto|on top of)\b)",
        "is ",
        text,
    )


def _as_state(rest: str) -> str:
    """ "the red cube resting on top of the green cube" -> "the red cube should be on top of the green cube"; "the
    drawer open, with the block in it" -> "the drawer should be open and the block in it"; a sentence that already
    has its verb is left as said."""
    rest = re.sub(
        r",?\s*\bwith ((?:the|a|an) [a-z' ]+?) (?:" + _PARTICIPLES + r" )?(in|inside|on|on top of) it\b",
        r" and \1 \2 it",
        rest,
    )
    # "the objective is for the sauce to be inside the basket": "for X to be" is "X should be"
    rest = re.sub(r"^((?:the|a|an) [a-z' -]+?) to be (?:" + _PARTICIPLES + r" )?", r"\1 should be ", rest)
    return re.sub(
        r"^((?:the|a|an) [a-z' -]+?) " + _PARTICIPLES + r" (?=(?:in|inside|into|on|onto|on top of|in front "
        r"of|next to|beside|behind|at)\b)",
        r"\1 should be ",
        rest,
    )


def _tower(text: str) -> str:
    """A stack said by its levels: "a tower: blue at the bottom, green in the middle, red on top" -> "stack the green
    on the blue, then the red on the green"; "... with the blue block at its base and the red block at the top" (two
    levels) -> "put the red block on the blue block"."""
    det = r"(?:the )?"
    thing = r"((?:[a-z]+ )?[a-z]+)"
    bottom = rf"{det}{thing} (?:at|on|as|forming|for) (?:the |its |their )?(?:bottom|base|foot)"
    middle = rf"{det}{thing} (?:in|at) (?:the |its )?(?:middle|centre|center)"
    top = rf"{det}{thing} (?:on top|at (?:the |its )?top|on (?:the )?top|up top|at the summit)"
    sep = r"\s*(?:,\s*(?:and |then )?|;\s*| and | then )\s*"
    lead = (
        r"^(?:(?:build|make|stack|assemble|create|form)(?: me| us)? (?:a|the|one) )?(?:should be |is )?"
        r"(?:a |the )?(?:three-block |two-block |3-block |2-block )?(?:tower|stack|pile)"
        r"(?: of (?:three|two|3|2|the) (?:blocks|cubes))?\s*(?::|with|where|in which|-+)?\s*"
    )
    m = re.fullmatch(lead + bottom + sep + middle + sep + top + r"\s*[.!]?", text)
    if m:
        low, mid, up = m.groups()
        return f"stack the {mid} on the {low}, then the {up} on the {mid}"
    m = re.fullmatch(lead + bottom + sep + top + r"\s*[.!]?", text)
    if m:
        low, up = m.groups()
        return f"put the {up} on the {low}"
    return text


def _supported_by(text: str) -> str:
    """ "position the red cube so that it is supported by the blue cube": where it goes, said as what holds it up;
    "push the red block such that it comes to rest inside the green zone": where it ends up."""
    text = re.sub(
        r"^((?:push|slide|nudge|shove|move|put|place|set|get) (?:the|a|an) [a-z ]+?),? (?:so|such) (?:that )?it "
        r"(?:comes to rest|ends up|lands|finishes|stops|rests|sits|ends) (in|inside|on|into|onto|on top of) ",
        r"\1 \2 ",
        text,
    )
    return re.sub(
        r"^((?:position|place|put|set|move|arrange|get|stand) (?:the|a|an) [a-z ]+?),? so (?:that )?it(?:'s| is| sits|"
        r" rests| stands| ends up)?(?: upright| flat| level| steady| securely)? (?:supported by|held up by|resting on|"
        r"sitting on|standing on|on top of|balanced on|on|(in|inside)) ",
        lambda m: f"{m.group(1)} {m.group(2) or 'on'} ",
        text,
    )


def _wished_lifted(text: str) -> str:
    """ "i'd like the red cube up off the table": a thing wished up, off what it stands on, is lifted."""
    return re.sub(
        r"^(?:i want|i'd like|i would like|id like|i need|want) ((?:the|a|an) [a-z ]+?) (?:up )?(?:off the table|"
        r"off the ground|in the air|up in the air|up off the table|clear of the (?:table|surface)|lifted|raised|"
        r"held up)\b",
        r"lift \1",
        text,
    )


def _wants_a_scrub(text: str) -> str:
    """ "plate wants a good scrub with the sponge", "the plate needs a wipe": a thing said to need cleaning is
    scrubbed."""
    return re.sub(
        r"^((?:the |that |this )?[a-z ]+?) (?:wants|needs|could do with|could use|deserves) (?:a |another )?"
        r"(?:good |proper |quick |thorough |little )?(scrub|wipe|clean|wash|rub|polish)(?:ing)?\b",
        r"\2 \1",
        text,
    )


def end_state_framed(text: str) -> str:
    """The state a specification frames, said plainly (see the module's docstring); the text itself when it frames
    nothing."""
    text = formal_words(text)
    text = _WHEN_AFTER.sub("", _WHEN.sub("", text))
    text = _POSSIBLE.sub(r"\1", text)
    m = _FRAME.match(text) or _AIM.match(text)
    if not m:
        return _tower(_passive(_wants_a_scrub(_wished_lifted(_supported_by(text)))))
    rest = text[m.end() :]
    towered = _tower(rest)
    return towered if towered != rest else _as_state(rest)
