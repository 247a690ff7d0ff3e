"""Which one of several of a kind: ordinals, superlatives, sides and negation brought to the forms perception
reads ("leftmost bowl", "second leftmost bowl", "farthest block", "bowl not on cabinet", "block not blue").

English picks one of several things of one kind in a few ways: by counting in a direction ("the second bowl from
the left", "the last cup on the right"), by an extreme or a comparison ("the farther of the two", "the bowl nearest
the robot", "the highest bowl"), by a side ("the mug at the back"), or by ruling one out ("not the bowl on the
stove, the other one", "any bowl except the one near the box", "the non-blue block"). These rewrites run on a whole
sentence before it is split into clauses, so that "on the left" is never read as a destination and "the other one"
finds the kind it stands for.
"""

from __future__ import annotations

import re

from ...perception.colors import BASE_COLOURS

# A noun phrase of one to three words after its determiner (no preposition, relative pronoun or negation in it).
_STOP = (
    r"(?:on|in|at|to|from|onto|into|inside|beside|with|for|that|which|who|not|of|and|or|but|the|a|an|is|are|it|them|"
    r"one|ones|then|near|by|alone|where|sitting|behind|between|beyond|"
    r"standing|lying|resting|placed|goes|go|belongs|belong|needs|should|must|will|gets|sits|ends)"
)
_WORD = rf"(?!{_STOP}\b)[\w-]+"
NP = rf"(?:{_WORD} ){{0,2}}{_WORD}"
_LAZY_NP = rf"(?:{_WORD} ){{0,2}}?{_WORD}"  # the fewest words before what follows ("cream cheese" of "... goes")
DET = r"(?:the|a|an|any|every|each|whichever)"
# A side, as the qualifier perception knows for it.
SIDES = {"left": "leftmost", "right": "rightmost", "front": "nearest", "back": "farthest", "rear": "farthest"}
_OPPOSITE = {"left": "right", "right": "left", "front": "back", "back": "front", "rear": "front", "top": "bottom"}
_OPPOSITE["bottom"] = "top"
RANKS = {"first": 1, "1st": 1, "second": 2, "2nd": 2, "third": 3, "3rd": 3, "fourth": 4, "4th": 4, "fifth": 5}
RANK_WORDS = {1: "", 2: "second ", 3: "third ", 4: "fourth ", 5: "fifth "}
# Comparatives and superlatives of position, as perception's qualifier words.
EXTREMES = {
    "farther": "farthest",
    "further": "farthest",
    "furthest": "farthest",
    "farthest": "farthest",
    "rearmost": "farthest",
    "backmost": "farthest",
    "hindmost": "farthest",
    "nearer": "nearest",
    "closer": "closest",
    "closest": "closest",
    "nearest": "nearest",
    "frontmost": "nearest",
    "foremost": "nearest",
    "higher": "top",
    "highest": "top",
    "upper": "upper",
    "uppermost": "top",
    "topmost": "top",
    "lower": "lower",
    "lowest": "bottom",
    "lowermost": "bottom",
    "bottommost": "bottom",
    "leftmost": "leftmost",
    "rightmost": "rightmost",
    # size, as perception's qualifiers "largest" and "smallest" (perception/qualifiers.py)
    "bigger": "largest",
    "larger": "largest",
    "biggest": "largest",
    "largest": "largest",
    "smaller": "smallest",
    "smallest": "smallest",
    "tinier": "smallest",
    "tiniest": "smallest",
}
_EXTREME = "|".join(EXTREMES)
_QUALIFIER_WORDS = frozenset([*EXTREMES.values(), *EXTREMES, "middle", "centre", "center", "top", "bottom"])
_SIDE = r"(left|right|front|back|rear)"
# counting may also run from the top or the bottom of a stack ("the second drawer from the top")
_COUNT_SIDE = r"(left|right|front|back|rear|top|bottom)"
_COUNT_SIDES = {**SIDES, "top": "top", "bottom": "bottom"}
_SIDE_TAIL = r"(?: side| hand side| end| edge)?"
# a side says where something is on the table, not where it is beside another ("the left side of the plate")
_SIDE_END = r"\b(?!(?: side| hand side| end| edge)? of\b)"
# where a noun phrase ends: a preposition, a conjunction, a verb of a stated goal, or punctuation ("the bowl on the
# left goes ..."; not "the left tray", where "left" is an adjective of the next noun)
_NP_END = (
    r"(?=$|[,.;:!?]|\s+(?:on|onto|in|into|to|and|then|with|from|at|over|inside|next|near|beside|by|goes|go|should|"
    r"must|has|have|needs|belongs|is|are|please|for|so|until|forwards?|backwards?|towards?|away|ahead|sitting|resting|"
    r"standing|lying|placed|out|open|closed|shut|up|off|behind|between|beyond)\b)"
)
_ME = r"(?:the robot|you|me|us|the arm|the gripper)"
# what is left once one is left alone: "the other one", "the remaining one" (of two)
_OTHER = r"(?:other|remaining|leftover|left-over|spare)"
_NEG = r"(?:is not|are not|was not|isn't|aren't|is n't)"


_RANKED_EXTREME = {
    "highest": "top",
    "uppermost": "top",
    "topmost": "top",
    "lowest": "bottom",
    "lowermost": "bottom",
    "bottommost": "bottom",
    "closest": "nearest",
    "frontmost": "nearest",
    "furthest": "farthest",
    "rearmost": "farthest",
}


def ordinals(text: str) -> str:
    """Counting in a direction: "the second bowl from the left" -> "the second leftmost bowl"; "the last cup on the
    right" and "the first cup from the right" -> "the rightmost cup"; "the last bowl from the left" -> "the
    rightmost bowl" (counted from the left, the last is at the other end); "the bowl second from the left" too."""

    def counted(rank_word: str, noun: str, prep: str, side: str) -> str:
        if rank_word == "last":
            side = _OPPOSITE[side] if prep == "from" else side
            return f"{_COUNT_SIDES[side]} {noun}"
        return f"{RANK_WORDS[RANKS[rank_word]]}{_COUNT_SIDES[side]} {noun}"

    ranks = "|".join([*RANKS, "last"])
    # counted from the robot ("the first bowl, counting from the robot,", "the second cup from you"): from the front
    text = re.sub(rf"\b(({ranks}) {NP}),? (?:counting |counted |starting )?from {_ME}\b,?", r"\1 from the front", text)
    # a rank and an extreme said as one word ("the second-highest drawer", "the second leftmost bowl"): counted
    # from that extreme
    text = re.sub(
        rf"\b({'|'.join(RANKS)})[- ](highest|uppermost|topmost|lowest|lowermost|bottommost|leftmost|rightmost|"
        r"nearest|closest|frontmost|farthest|furthest|rearmost)\b",
        lambda m: f"{m.group(1)} {_RANKED_EXTREME.get(m.group(2), m.group(2))}",
        text,
    )
    # counted from the top or the bottom of the thing it is part of ("the second drawer from the top of the cabinet"):
    # the count, then whose part it is
    text = re.sub(
        rf"\b({ranks}) (\w+) from the (top|bottom) of (the (?:\w+ ){{0,2}}\w+)",
        lambda m: f"{counted(m.group(1), m.group(2), 'from', m.group(3))} of {m.group(4)}",
        text,
    )
    # counted down from the top or up from the bottom ("the second drawer down", "the third shelf up")
    text = re.sub(
        rf"\b({ranks}) ({NP}) (down|up)\b(?! (?:on|onto|in|into|to)\b(?! the (?:cabinet|shelf|rack)))",
        lambda m: counted(m.group(1), m.group(2), "from", "top" if m.group(3) == "down" else "bottom"),
        text,
    )
    text = re.sub(  # "the second-from-left bowl"
        rf"\b({ranks})[- ](from|on)[- ](?:the[- ])?{_COUNT_SIDE} ({NP})",
        lambda m: counted(m.group(1), m.group(4), m.group(2), m.group(3)),
        text,
    )
    text = re.sub(
        rf"\b({ranks}) ({NP}) (from|on|at|in|to) the {_COUNT_SIDE}{_SIDE_TAIL}{_SIDE_END}{_NP_END}",
        lambda m: counted(m.group(1), m.group(2), m.group(3), m.group(4)),
        text,
    )
    return re.sub(
        rf"\b({NP}) (?:(?:that|which) is )?({ranks}) (from|on|at|in) the {_COUNT_SIDE}{_SIDE_TAIL}{_SIDE_END}"
        rf"{_NP_END}",
        lambda m: counted(m.group(2), m.group(1), m.group(3), m.group(4)),
        text,
    )


def extremes(text: str, push: bool = False) -> str:
    """Comparisons and extremes of position: "the farther of the two bowls" / "the farthest of the bowls" ->
    "the farthest bowl"; "the nearer one" -> "the nearest one"; "the highest bowl" -> "the top bowl"; "the block
    (that is) farther away from the robot" / "the bowl nearest you" -> "the farthest block" / "the nearest bowl";
    "the bowl at the back" / "on the left" -> "the farthest bowl" / "the leftmost bowl"; "the bowl nearest (to) the
    plate" -> "the bowl near the plate" (the one by another object)."""
    # "the more distant of the two": the farther
    text = re.sub(rf"\b({DET}) (?:more|most) (?:distant|remote)\b", r"\1 farthest", text)
    # "the near black bowl, not the far one": near and far said as adjectives ("the far left" is a side)
    text = re.sub(
        rf"\b({DET}) (near|far)(?= (?!(?:left|right|end|side|corner|edge|back|front|away|from|of)\b)[a-z])",
        lambda m: f"{m.group(1)} {'nearest' if m.group(2) == 'near' else 'farthest'}",
        text,
    )
    # "the less elevated bowl", "the more raised one": lower and higher
    text = re.sub(rf"\b({DET}) less (?:elevated|raised|high)\b", r"\1 lower", text)
    text = re.sub(rf"\b({DET}) more (?:elevated|raised)\b", r"\1 higher", text)
    if not push:
        # "the black bowl more to the right": the one furthest that way
        text = re.sub(
            rf"\b({DET}) ({NP}) (?:(?:a bit|a little|slightly) )?(?:more|further|farther) to the (left|right)\b",
            r"\1 \3most \2",
            text,
        )
    # "the block further from the robot on top of the one closer to it": "it" is the robot the comparison was
    # said against before
    if re.search(r"\b(?:farther|further|closer|nearer) (?:away )?(?:from|to) the robot\b", text):
        text = re.sub(r"\b(farther|further|closer|nearer) (from|to) it\b", r"\1 \2 the robot", text)
    text = re.sub(
        rf"\b({_EXTREME}) (?:one )?of (?:the |these |those )?(?:(?:two|three|four|both|all) )?({NP})\b",
        lambda m: f"{EXTREMES[m.group(1)]} {_singular_phrase(m.group(2))}",
        text,
    )
    # "the further-back bowl", "the closer-in one": the comparison said before the noun as one word
    text = re.sub(rf"\b({DET}) (?:farther|further)-(?:back|away|out) ", r"\1 farthest ", text)
    text = re.sub(rf"\b({DET}) (?:nearer|closer)-(?:in|up|forward|front) ", r"\1 nearest ", text)
    # "whichever of the two blocks is farther": the same as "whichever block is farther"
    text = re.sub(
        rf"\bwhichever (?:one )?of (?:the |these |those )?(?:(?:two|three|four|both|all) )?({NP}) (?=(?:is|are) )",
        lambda m: f"whichever {_singular_phrase(m.group(1))} ",
        text,
    )
    # "whichever bowl is closest to you": the same as "the bowl that is closest to you"
    text = re.sub(rf"\bwhichever ({NP}) (?:is|are) (?=(?:the )?(?:{_EXTREME}|far|near)\b)", r"the \1 that is ", text)
    # an extreme said first, without a determiner ("topmost black bowl: onto the plate", "lowest bowl, plate")
    text = re.sub(rf"(^|[,:;.] )({_EXTREME}) (?={_WORD}\b)", r"\1the \2 ", text)
    text = re.sub(r"\b(left|right)-hand side\b", r"\1 side", text)
    text = re.sub(rf"\b({DET}) (left|right)-hand(?:ed)? ", r"\1 \2most ", text)
    if push:  # "push the cup closer to you", "further away": the way to move it
        return _sides(text)
    where = r"(?:(?:that|which) (?:is|are) |(?:sitting|standing|lying|resting|placed) )?"
    # "the bowl furthest to the left", "the bowl farthest left": the leftmost
    text = re.sub(
        rf"\b({DET}) ({NP}) {where}(?:the )?(?:farthest|furthest|farther|further|most|far) "
        rf"(?:to |on |toward |towards )?(?:the robot's |the robot |your |its |the )?"
        rf"(left|right)\b(?! of)",
        lambda m: f"{m.group(1)} {SIDES[m.group(3)]} {m.group(2)}",
        text,
    )
    # "the bowl nearest the back", "closest to the front": the side it is nearest
    text = re.sub(
        rf"\b({DET}) ({NP}) {where}(?:the )?(?:nearest|closest|nearer|closer) (?:to )?the {_SIDE}{_SIDE_TAIL}"
        rf"{_SIDE_END}",
        lambda m: f"{m.group(1)} {SIDES[m.group(3)]} {m.group(2)}",
        text,
    )
    # "the drawer nearest the floor": the bottom one; nearest the ceiling, the top one
    text = re.sub(
        rf"\b({DET}) ({NP}) {where}(?:the )?(?:nearest|closest|nearer|closer) (?:to )?the (floor|ground|ceiling|sky)\b",
        lambda m: f"{m.group(1)} {'bottom' if m.group(3) in ('floor', 'ground') else 'top'} {m.group(2)}",
        text,
    )
    # "the bowl sitting higher", "whichever bowl is highest up": the top one
    text = re.sub(
        rf"\b({DET}) ({NP}) (?:(?:that|which) )?(?:is |are )?(?:sitting |standing |resting |placed |set )?"
        # "the bowl that sits lowest": where it is, said by a verb
        rf"(?:(?:sits|stands|rests|lies|sit|stand|rest|lie) )?"
        rf"(higher|highest|lower|lowest|uppermost|lowermost)(?: up| down)?\b(?! than)",
        lambda m: f"{'the' if m.group(1) == 'whichever' else m.group(1)} {EXTREMES[m.group(3)]} {m.group(2)}",
        text,
    )
    relative = r"(?:(?:that|which) (?:is|are) |(?:sitting|standing|lying|resting|placed) )"
    text = re.sub(
        rf"\b({DET}) ({NP}) (?:{relative}(?:the )?(?:(?:farther|further|farthest|furthest)(?: away| back| out)?|"
        rf"far (?:away|off|back|out))"
        rf"(?: from {_ME}\b)?(?=$|[\s,.])(?! from\b)|(?:the )?(?:(?:farther|further)(?: away| back| out)? from {_ME}\b|"
        rf"(?:farthest|furthest)(?: away| back| out)?(?: from {_ME}\b)?(?=$|[\s,.])(?! from\b)|"
        # "the one further back goes on the plate": the comparison with its direction, after the noun
        rf"(?:farther|further) (?:back|away|out)(?=$|[\s,.])(?! from\b)|"
        # "the mug (that is) far away (from you)": far from the robot, the farthest
        rf"far (?:away|off|back|out)(?: from {_ME}\b)?(?=$|[\s,.])(?! from\b)))",
        lambda m: f"{m.group(1)} farthest {m.group(2)}",
        text,
    )
    text = re.sub(
        rf"\b({DET}) ({NP}) {where}(?:the )?(nearer|closer|nearest|closest)(?: to)? {_ME}\b",
        lambda m: f"{m.group(1)} nearest {m.group(2)}",
        text,
    )
    text = re.sub(
        rf"\b({DET}) ({NP}) {where}(?:the )?(nearer|closer|nearest|closest)(?: to)? (?!{_ME}\b)(the |a )",
        lambda m: f"{m.group(1)} {m.group(2)} near {m.group(4)}",
        text,
    )
    # "the one closer to the robot": "one" stands for the kind named before (parse.py), the comparison before it
    text = re.sub(
        rf"\b(the|that) ((?!other\b)[a-z]+ )?ones? (?:(?:that|which) (?:is|are) )?(nearer|closer|nearest|closest|"
        rf"farther|further|farthest|furthest)(?: away)?(?: to| from)? {_ME}\b",
        # "the blue one nearer to you": its look stays with it
        lambda m: f"the {EXTREMES[m.group(3)]} {m.group(2) or ''}one",
        text,
    )
    # "the closest bowl to you": the extreme is said before the noun, the point of view after it
    text = re.sub(rf"\b(nearest|farthest|closest|furthest) ({NP}) (?:to|from) {_ME}\b", r"\1 \2", text)
    return _sides(text)


def _sides(text: str) -> str:
    """ "the bowl on the left" / "at the back" -> "the leftmost bowl" / "the farthest bowl"; an extreme before the
    noun as perception's word ("the farther block", "the lower bowl", "the nearer one")."""
    # "the front one", "the back bowl": a side said as an adjective ("the front of the stove" is a place)
    text = re.sub(
        rf"\b({DET}) (front|back|rear)"
        rf"(?= (?:ones?\b|(?!{_STOP}\b)(?!(?:side|end|edge|left|right|corner|part|half)\b)[a-z]))",
        lambda m: f"{m.group(1)} {SIDES[m.group(2)]}",
        text,
    )
    # "the one up high", "the bowl that is not down low": the top or the bottom one
    text = re.sub(
        rf"\b({DET}) ({NP}) (?:(?:that|which) (?:is|are) |(?:sitting|standing|resting|lying) )?(not )?"
        r"(up high|high up|down low|low down)\b",
        lambda m: _up_or_down(m.group(1), m.group(2), bool(m.group(3)), "high" in m.group(4)),
        text,
    )
    # the robot's own left is the left perception counts in ("on the robot's left", "on your right", "on its left")
    text = re.sub(r"\b(on|at|to) (?:the robot's|the robot|your|its|my) (left|right)\b", r"\1 the \2", text)
    # "the mug that is off to the left", "the bowl (and) over on the right": a side said with an adverb of place,
    # or after a relative; a bare "to the left" after a thing stays where it goes ("move the mug to the left")
    text = re.sub(
        rf"\b({DET}) ({NP})(?: and|,)? (?:(?:that|which) (?:is|are) (?:(?:off|over|way|out|far) )?|"
        rf"(?:sitting|standing|lying|resting) (?:(?:off|over|way|out) )?|(?:off|over|way) )(?:to|on|at) the "
        rf"{_SIDE}{_SIDE_TAIL}{_SIDE_END}{_NP_END}",
        lambda m: f"{m.group(1)} {SIDES[m.group(3)]} {m.group(2)}",
        text,
    )
    text = re.sub(
        rf"\b({DET}) ({NP}) (?:(?:that|which) (?:is|are) |(?:sitting|standing|lying) )?(?:on|at|in) the (?:far |very )?"
        rf"{_SIDE}{_SIDE_TAIL}{_SIDE_END}{_NP_END}",
        lambda m: f"{m.group(1)} {SIDES[m.group(3)]} {m.group(2)}",
        text,
    )
    text = re.sub(rf"\b({DET}) ({NP}) (?:(?:that|which) (?:is|are) )?in front{_NP_END}", r"\1 nearest \2", text)
    # "the one in front", "the one at the back": "one" stands for the kind named before (parse.py)
    text = re.sub(r"\bthe one (?:that is )?in front\b(?! of)", "the nearest one", text)
    text = re.sub(r"\bthe one (?:that is )?(?:at|in) the (?:back|rear)\b(?! of)", "the farthest one", text)
    # after a determiner or a possessive ("the cabinet's lowest drawer")
    return re.sub(rf"\b({DET}|\w+'s?) ({_EXTREME}) ", lambda m: f"{m.group(1)} {EXTREMES[m.group(2)]} ", text)


def _up_or_down(det: str, noun: str, ruled_out: bool, high: bool) -> str:
    """ "the bowl up high" -> "the top bowl"; "the bowl not down low" -> "the bowl not bottom"."""
    where = "top" if high else "bottom"
    return f"{det} {noun} not {where}" if ruled_out else f"{det} {where} {noun}"


def negations(text: str) -> str:
    """Ruling one out, as "<kind> not <what rules it out>": "not the bowl on the stove, the other one" / "the other
    block, not the blue one" / "any bowl except the one near the box" / "the bowl other than the one further back" /
    "the non-blue block" / "the block that is not the blue one" / "leave the bowl on the cabinet alone and put the
    other bowl on the plate"; then a side or an extreme after "not" as its qualifier ("not on the left" -> "not
    leftmost")."""
    # "the bowl over by the cookies": "over" only says it is some way off
    text = re.sub(r"\b(?:over|up|down|back) (?=(?:by|near|next to|beside)\b)", "", text)
    text = _corrections(text)
    # "all but the blue block", "everything except the bowl on the stove": a quantifier with its exception names the
    # rest of the exception's kind, ruled out by the exception's own words (or where it is, when a destination
    # follows)
    text = re.sub(
        rf"\b(?:all|everything|anything|any|each|every one|whichever)(?: (?:one|ones|of them))? "
        rf"(?:but|except(?: for)?|other than|apart from|besides|save(?: for)?|excluding) (?:the|a|an) ({NP})"
        rf"((?: (?:on|in|near|next to|by|beside|under|at) (?:the|a|an) {NP}(?= (?:goes|go|into|onto|to|in|on)\b))?)",
        lambda m: _ruled_out_noun(m.group(1), m.group(2).strip()),
        text,
    )
    # "..., but not the one in the middle": a correction of the clause's object, as "..., not the one ..."
    text = re.sub(r",\s*but not ((?:the|that|this) ones? [^,;:.!]*)[.!]?$", r", not \1", text)
    # "leave the one in the drawer, plate the bowl on the cabinet": the one left where it is, said by where it is
    # alone, is ruled out of the request after it (no "other" there to carry it)
    text = re.sub(
        r"^(?:leave|ignore|skip|do not touch|do not move|forget) (?:the|that) one "
        r"((?:in|on|at|by|near|next to|beside|under|inside|on top of)\b[^,;.]+?)"
        r"(?: alone| be| where it is| in place| as it is)?\s*[,;.] (?:and |but |then )?(.+)$",
        lambda m: re.sub(r"\bthe other\b", "the", m.group(2), count=1) + f", not the one {m.group(1)}",
        text,
    )
    # "leave the centre bowl alone; the other bowl goes ...", "ignore the bowl on the stove and put the other one
    # ...": the one left alone is ruled out, by where it is or by its own words
    text = re.sub(
        rf"^(?:leave|ignore|skip|do not touch|do not move|forget|never mind) the ({NP})"
        rf"(?: (?!alone\b|be\b|where it|in place\b|as it is\b)([^,;.]+?))?"
        rf"(?: alone| be| where it is| in place| as it is| where it stands)?[,;.]? (?:and |but |then )?"
        rf"(?:just |simply |only )?((?:(?:i|we) (?:want|need|would like) |\w+(?: up)? )?)the {_OTHER} (one|{NP})\b",
        _left_alone,
        text,
    )
    # "leave the bowl on top of the cabinet; take the one in the top drawer ...": the one left where it is, only
    # said (not put there), and "the one" after it is of its kind
    text = re.sub(
        rf"^(?:leave|ignore|skip|forget) (the {NP} (?:on|in|inside|on top of|next to|by|near|beside|at) [^,;.]+?)"
        rf"(?: alone| be| where it is| in place| as it is)?\s*[;.]\s*(?=(?:and |but |then )?(?:just |only )?"
        rf"(?:\w+(?: up)? )?the one\b)",
        r"there is \1. ",
        text,
    )
    # "leave the bowl on the cabinet alone and put the other bowl ...": the one left alone is ruled out
    text = re.sub(
        rf"^(?:leave|ignore|skip|do not touch|do not move|forget|never mind) the ({NP}) ([^,;.]+?)"
        rf"(?: alone| be| where it is| in place| as it is)?[,;]? (?:and |but |then )?(\w+(?: up)?) "
        rf"the {_OTHER} (?:one|{NP})\b",
        r"\3 the \1 not \2",
        text,
    )
    # "not the blue one, lift the other block": ruled out by an attribute, then the request for the other of the kind
    text = re.sub(
        rf"^not the ({_WORD}) ones?\s*[,:;]?\s*(?:but |rather )?((?:\w+(?: up)? )?)the other ({NP})\b",
        r"\2the \3 not \1",
        text,
    )
    # "not the bowl in the middle, the other one by the plate": the other one picked out by where it is, which says
    # which on its own
    text = re.sub(
        rf"^not the ({NP})(?: [^,:;]+?)?(?: ones?)?\s*[,:;]\s*(?:but |rather )?the (?:other )?(?:one|{NP}) (?:over )?"
        rf"((?:by|near|next to|beside|on|in|at|under|behind|in front of) (?:the|a|an) [^,:;.!]+)",
        r"the \1 \2",
        text,
    )
    # "not the bowl on the burner, the other one goes ..." / "not the blue block but the other one"
    text = re.sub(
        rf"^not the ({NP})( [^,:;]+?)?(?: ones?)?\s*[,:;]?\s*(?:but |rather )?the other (?:one|{NP})\b",
        lambda m: _ruled_out_noun(m.group(1), (m.group(2) or "").strip()),
        text,
    )
    # "the other block, not the blue one" / "the other bowl, not the one on the stove"
    text = re.sub(rf"\bthe other ({NP}),? (?:and )?not the ({_WORD}) ones?\b", r"the \1 not \2", text)
    # (a parenthetical "..., not the one between A and B, goes on ..." closes with its comma)
    text = re.sub(rf"\bthe other ({NP}),? (?:and )?not the (?:ones?|{NP}) ([^,;:]+),?", r"the \1 not \2", text)
    # "any bowl except (for) the one near the box", "the bowl other than the one further back", "... the blue one"
    but = r"(?:except(?: for)?|but not|other than|apart from|besides|save for|excluding|rather than)"
    text = re.sub(rf"\b{DET} ({NP}),? {but} (?:the|that) ({_WORD}) ones?\b", r"the \1 not \2", text)
    # "the carton other than the orange juice goes in ...": ruled out by a thing named in full
    text = re.sub(
        rf"\b{DET} ({NP}),? {but} (?:the|a|an) (?!ones?\b)({NP})"
        rf"(?=\s+(?:goes|go|into|in|onto|on|to|should|please)\b|\s*[,;:.!]|\s*$)",
        r"the \1 not \2",
        text,
    )
    text = re.sub(rf"\b{DET} ({NP}),? {but} (?:the|that) (?:ones?|{NP}) ([^,;:]+),?", r"the \1 not \2", text)
    # "any bowl but the one on the cabinet": "but" rules one out only after "any" (a "but" after "the bowl" joins)
    text = re.sub(rf"\b(?:any|whichever) ({NP}),? but (?:the|that) (?:ones?|{NP}) ([^,;:]+),?", r"the \1 not \2", text)
    # "the sauce that is not (the) barbecue sauce": ruled out by the words of its own kind
    text = re.sub(rf"\b{DET} ({NP}) (?:(?:that|which) )?{_NEG} (?:the |a |an )?({NP})\b", _not_own_kind, text)
    # "the box that is not the cream cheese goes ...", "the bottle that isn't the bbq sauce or the salad dressing,":
    # ruled out by things of other kinds named in full (the reading below would drop them as "the <one> <where>")
    text = re.sub(
        rf"\b{DET} ({NP}) (?:(?:that|which) )?{_NEG} the (?!ones?\b)({_LAZY_NP})(?: (?:or|nor) (?:the )?({_LAZY_NP}))?"
        rf"(?=\s+(?:goes|go|into|in|onto|on|to|should|please)\b|\s*[,;:.!]|\s*$)",
        _not_other_kinds,
        text,
    )
    # "whichever block is not the blue one", "the block that is not the blue one"
    text = re.sub(rf"\b{DET} ({NP}) (?:(?:that|which) )?{_NEG} the ({_WORD}) ones?\b", r"the \1 not \2", text)
    text = re.sub(rf"\b{DET} ({NP}) (?:(?:that|which) )?{_NEG} the (?:ones?|{NP}) ", r"the \1 not ", text)
    text = re.sub(rf"\bwhichever ({NP}) {_NEG} ", r"the \1 not ", text)
    # "the peg that is not round", "the block which is not red": ruled out by an attribute
    text = re.sub(
        rf"\b{DET} ({NP}) (?:that|which) {_NEG} (\w+)\b(?! (?:the|a|an|of|to)\b)",
        lambda m: f"the {m.group(1)} not {m.group(2)}" if is_adjective(m.group(2)) else m.group(0),
        text,
    )
    # an apposition says which: "the bowl, the one not on the stove, ..." / "the block, i mean the one on the left,"
    text = re.sub(
        rf"\bthe ({NP}),? (?:i mean |that is |namely |it is |the one that is )?the ones? ([^,;:]+),?",
        lambda m: f"the {_unordered(m.group(1), m.group(2))} {m.group(2)}",
        text,
    )
    # "the non-blue block", "the non red one"
    text = re.sub(r"\bthe non[- ]?(\w+) (\w+)\b", r"the \2 not \1", text)
    text = _trailing_not(text)
    text = _positive_of_ruled_out(text)
    # a side or an extreme after "not" is the qualifier that would pick the one ruled out
    return re.sub(
        rf"\b(?:(?:that|which) )?(?:(?:is|are) )?not (?:the )?((?:up |down |over )?(?:on|at|in) the (?:far )?{_SIDE}"
        rf"{_SIDE_TAIL}{_SIDE_END}{_NP_END}|(?:further|farther) (?:back|away)\b(?! from)|"
        rf"(?:{_EXTREME})\b(?: one)?(?: away| back)?(?: (?:from|to) {_ME}\b)?)",
        lambda m: f"not {_ruled_out(m.group(1))}",
        text,
    )


def _unordered(np_: str, said: str) -> str:
    """ "the second black bowl, the one farther away from you": where the apposition says it is picks it out; the
    ordinal said first only counted it as another of its kind."""
    if re.match(r"(?:second|other|2nd) ", np_) and re.match(
        rf"(?:(?:further|farther|closer|nearer) |(?:{_EXTREME})\b|(?:on|at|in) the (?:far )?{_SIDE}\b)", said
    ):
        return np_.split(" ", 1)[1]
    return np_


def _positive_of_ruled_out(text: str) -> str:
    """ "the cube not green ... on the one that is": "the one that is" after a thing ruled out by an attribute or a
    place is the one of that kind it rules in ("the green cube"; "the bowl on the stove")."""
    m = re.search(rf"\bthe ({NP}) not ([\w ]+?)(?= (?:and|then|on|onto|in|into|to|goes|go)\b|[,;.]|$)", text)
    if m is None:
        return text
    kind, what = m.group(1), m.group(2).strip()
    said = f"the {what} {kind}" if is_adjective(what) else f"the {kind} {what}"
    return text[: m.end()] + re.sub(
        r"\bthe ones? (?:that|which) (?:is|are)(?: (?:so|that way|like that))?(?=\s*(?:$|[,;.]|and\b|then\b))",
        said,
        text[m.end() :],
        count=1,
    )


def _corrections(text: str) -> str:
    """A correction said first: "not the tomato sauce, the bbq one" / "not the one on the cabinet - the bowl on the
    stove, ..." names the thing meant after the one ruled out; the positive phrase stands (its "one" is of the kind
    ruled out). Ruled out by another kind ("not the plate, the bowl"), the other thing is still named (a "there
    is" sentence first), so that it must be in the scene. "the other one" after it is `negations`' own form."""
    m = re.match(
        rf"not (?:the|a|an) ((?:{_WORD} ){{0,2}}(?:{_WORD}|one))((?: [^,:;.]+?)?)\s*[,:;.]\s*(?:but |rather |i mean "
        rf"|instead )?(the|a|an) (?!other\b)((?:{_WORD} ){{0,2}}(?:{_WORD}|one))\b",
        text,
    )
    if not m:
        return _contrasts(text)
    ruled, said = m.group(1).split(), m.group(4).split()
    rest = text[m.end() :]
    if said[-1] == "one" and ruled[-1] != "one":
        return f"{m.group(3)} {' '.join([*said[:-1], _singular_phrase(ruled[-1])])}{rest}"
    if ruled[-1] == "one" or said[-1] == "one" or _singular_phrase(ruled[-1]) == _singular_phrase(said[-1]):
        return f"{m.group(3)} {m.group(4)}{rest}"
    return f"there is the {m.group(1)} . {m.group(3)} {m.group(4)}{rest}"


def _contrasts(text: str) -> str:
    """ "push the cheese, not the plate, to the stove": another kind ruled out in passing is still named (it must be
    in the scene), and the clause reads without it; "put the bowl on the plate: not the one on the cabinet, the
    other one" is the clause's object ruled out by where it is ("..., not the one on the cabinet")."""
    m = re.search(rf"\b(the|a|an) ({NP}),? not (?:the|a|an) ({NP}),\s*", text)
    if m and _singular_phrase(m.group(2)).split()[-1] != _singular_phrase(m.group(3)).split()[-1]:
        return f"there is the {m.group(3)} . {text[: m.start()]}{m.group(1)} {m.group(2)} {text[m.end() :]}"
    return re.sub(
        rf"^(.+?)\s*[:,;]\s*not (the|that) (ones?|{NP}) ([^,;:.]+?),? (?:but )?the other (?:ones?|{NP})\s*$",
        r"\1, not \2 \3 \4",
        text,
    )


# Words that say where a thing is ("on the cabinet", "that sits by the box", "closest to the plate").
_WHERE_WORDS = (
    r"\b(?:on|in|inside|near|next|by|beside|under|underneath|at|from|between|behind|to|of|that|which|sitting|"
    r"standing|resting|lying|closest|nearest|farthest|furthest)\b"
)


def _left_alone(m: re.Match) -> str:
    """ "leave the <kind> <where> alone; the other <kind> goes ...": the other is the kind, not where the one left
    alone is (or not its own words: "the centre bowl" -> "bowl not centre")."""
    left, where, verb, other = m.group(1).split(), (m.group(2) or "").strip(), m.group(3), m.group(4)
    where = re.sub(r"(?:^|\s+)(?:and|but|then)$", "", where).strip()  # the join to the request, not where
    if where and not re.search(_WHERE_WORDS, where):  # "leave the far black bowl and ...": all of it its name
        left, where = [*left, *where.split()], ""
    # a side or the centre as perception's qualifier word ("left" -> "leftmost", "centre" -> "middle")
    words = {**SIDES, "centre": "middle", "center": "middle", "central": "middle"}
    placed = [w for w in left[:-1] if w in words or w in _QUALIFIER_WORDS or w in ("far", "near")]
    # "the far black bowl ... the other one": the other black bowl, not the far one
    kind = " ".join([w for w in left if w not in placed] if placed and not where else left[-1:])
    kind = kind if other == "one" else other
    ruled = _ruled_out(where) if where else " ".join(words.get(w, w) for w in left[:-1] if w not in kind.split())
    if not ruled:
        return m.group(0)
    if re.search(r"\b(?:it|them)\b", m.string[m.end() :]):  # "... on top of it": the one left alone, named first
        return f"there is the {' '.join([*left, where]).strip()}, {verb}the {kind} not {ruled}"
    return f"{verb}the {kind} not {ruled}"


def is_adjective(word: str) -> bool:
    """A word the lexicon knows as an adjective ("round", "empty", "blue")."""
    from lemminflect import getAllLemmas

    pos = getAllLemmas(word)
    return "ADJ" in pos or word in BASE_COLOURS


def _not_other_kinds(m: re.Match) -> str:
    """ "the box not cream cheese (nor chocolate pudding)" when each thing ruled out is of another kind than the
    head."""
    head = m.group(1).split()[-1]
    ruled_out = [g for g in (m.group(2), m.group(3)) if g]
    if any(g.split()[-1] == head for g in ruled_out):
        return m.group(0)
    return f"the {m.group(1)} not {' nor '.join(ruled_out)}"


def _not_own_kind(m: re.Match) -> str:
    kind, other = m.group(1).split(), m.group(2).split()
    if len(other) < 2 or other[-1] != kind[-1]:
        return m.group(0)
    return f"the {m.group(1)} not {' '.join(other[:-1])}"


def _trailing_not(text: str) -> str:
    """ "put the black bowl on the plate, not the one on the cabinet" / "..., not the bowl on the stove": a
    correction after the clause rules out one of the kind of the clause's object ("the black bowl not on the
    cabinet"). (A correction of the place, "..., not on the stove", is dropped as a trailing clause.)"""
    m = re.fullmatch(
        rf"(.+?),? (?:and |but )?(?:just |only |simply )?not (?:the|a|an|that|this) (?:({_WORD}) ones?|ones?|({NP}))"
        rf"(?: ([^,;:]+?))?\s*([.!?]*)",
        text,
    )
    if not m:
        return text
    end = m.group(5)  # the sentence's end mark stays at its end
    main, named, rest = m.group(1), m.group(3), (m.group(4) or m.group(2) or "").strip()
    obj = re.search(rf"\b(the|a|an) ({NP})(?=\s|$)", main)
    if obj is None:
        return text
    head = _singular_phrase(obj.group(2)).split()[-1]
    if set(obj.group(2).split()) & set(_QUALIFIER_WORDS) and _ruled_out(rest or "") in _QUALIFIER_WORDS:
        return main  # "the bottom drawer, not the middle one": the qualifier said already picks it out
    located = re.match(
        r"\s+(?:next to|beside|by|near|between|(?:that|which) (?:is|are|sits?|stands?) \w+) ", main[obj.end() :]
    )
    # two places after it: the first says where it is ("the bowl on top of the cabinet on the plate"), when what is
    # ruled out is of its kind ("..., not the one in the drawer"; "into the container that is not the mug" rules out
    # another thing's kind)
    same_kind = named is None or _singular_phrase(named).split()[-1] == head
    two_places = same_kind and re.match(
        r"\s+(?:on top of|on|in|inside|at|from) (?:the )?"
        r"(?:(?!goes\b|go\b|belongs?\b|should\b|must\b|needs?\b)[a-z']+ )+?"
        r"(?:on top of|onto|on|into|inside|in|to) the ",
        main[obj.end() :],
    )
    if located or two_places or obj.group(2).endswith(" next") and main[obj.end() :].startswith(" to "):
        return main  # "the black bowl next to the ramekin ..., not the one further back": where it is picks it out
    if named is not None:
        said = _singular_phrase(named).split()
        if said[-1] != head:
            return text
        if not rest and len(said) > 1:  # "..., not the blue block": its words rule it out
            rest = " ".join(said[:-1])
    if not rest:
        return text
    return f"{main[: obj.end()]} not {_ruled_out(rest)}{main[obj.end() :]}{end}"


def _ruled_out(what: str) -> str:
    """What rules a candidate out, as perception reads it: a side or an extreme as its qualifier ("on the left" ->
    "leftmost", "further back" -> "farthest"), a place as a relation ("up on the cabinet" -> "on the cabinet"),
    an attribute as itself ("blue")."""
    what = re.sub(r"^(?:that is|which is|that|which|is|are|sitting|standing|lying|resting|placed) ", "", what.strip())
    what = re.sub(r"^(?:up|down|over) (?=on|in|at)\b", "", what)
    side = re.fullmatch(rf"(?:on|at|in) the (?:far )?{_SIDE}{_SIDE_TAIL}", what)
    if side:
        return SIDES[side.group(1)]
    m = re.fullmatch(rf"(?:the )?({_EXTREME})(?: one)?(?: away| back)?(?: (?:from|to) {_ME})?", what)
    if m:
        return EXTREMES[m.group(1)]
    if re.fullmatch(r"(?:further|farther) (?:back|away)", what):
        return "farthest"
    return what


def _ruled_out_noun(noun: str, rest: str) -> str:
    """ "not the blue block" -> "the block not blue"; "not the bowl on the stove" -> "the bowl not on the stove"."""
    words = noun.split()
    if len(words) > 1 and words[-1] in EXTREMES:  # "not the black bowl closest to you": the extreme rules it out
        noun, rest = " ".join(words[:-1]), f"{words[-1]} {rest}".strip()
        words = words[:-1]
    if rest:
        return f"the {noun} not {_ruled_out(rest)}"
    if len(words) > 1:
        return f"the {words[-1]} not {' '.join(words[:-1])}"
    return f"the other {noun}"  # "not the bowl, the other one": nothing rules it out


def _singular_phrase(phrase: str) -> str:
    from .phrases import singular

    return " ".join(singular(w) for w in phrase.split())


def partitive(text: str) -> str:
    """ "of the two black bowls, take the one on the cabinet ..." -> "take the black bowl on the cabinet ...": the
    kind said first stands for "the one" after it."""
    m = re.match(
        rf"(?:out )?of (?:the|these|those|all the) (?:(?:two|three|four|both|several|pair of|couple of) )?"
        rf"({NP}),\s*(.+)$",
        text,
    )
    # (or said without the comma, with its count: "from the two blocks lift the one that is further away")
    m = m or re.match(
        r"(?:out of|of|from|among|between) (?:the|these|those) (?:two|three|four|both|2|3|4) ((?:[a-z]+ )?[a-z]+s) "
        r"(?=(?:the|which|whichever|take|lift|pick|grab|put|place|move|get|choose|select)\b)(.+)$",
        text,
    )
    if not m:
        return text
    kind = _singular_phrase(m.group(1))
    return re.sub(r"\b(the|which|whichever)( \w+)? ones?\b", rf"\1\2 {kind}", m.group(2), count=1)


def _extreme_said_after(text: str) -> str:
    """ "the bowl that's up highest", "the block which is furthest away": an extreme said after its noun, before it
    ("the highest bowl")."""
    return re.sub(
        r"\bthe ([a-z]+) (?:that's|thats|that is|which is|which's) (?:up |down |the )?"
        r"(highest|lowest|farthest|furthest|"
        r"nearest|closest|leftmost|rightmost|topmost)(?: (?:up|down|away|off|of all|out))?\b"
        # (not "the box that's closest to the ceiling": nearest another thing is near it)
        r"(?=\s*(?:$|[,.;:!?-]|(?:away )?from (?:the robot|you|me)\b|(?:and|then|put|take|goes|should)\b))",
        r"the \2 \1",
        text,
    )


def qualify(text: str) -> str:
    """A sentence with its ordinals, extremes, sides and negations in perception's forms. A push keeps its words:
    there "further", "closer" and "to the left" say which way to move, not which object."""
    text = neither_nor(partitive(_extreme_said_after(text)))
    push = re.match(r"(?:push|shove|nudge|slide)\b", text) is not None
    return extremes(ordinals(negations(text)), push)


# Places along one line that a thing may be picked out by; ruling out all but one of them names the one left.
_RUNS = (("top", "middle", "bottom"), ("upper", "middle", "lower"))


def neither_nor(text: str) -> str:
    """ "the drawer that is neither the top one nor the middle one" -> "the drawer bottom": of three places along one
    line, ruling out two names the third ("not the top one, not the middle one" alike); anything else ruled out so is
    left as said (and read as a negation)."""

    def third(m: re.Match) -> str:
        ruled = {m.group(1), m.group(2)}
        for run in _RUNS:
            if ruled < set(run) and len(ruled) == 2:
                return f" {next(p for p in run if p not in ruled)}"
        return m.group(0)

    text = re.sub(
        r"\s*,?\s*(?:(?:that|which) (?:is|are) |(?:that|which)'s )?neither (?:the )?(\w+)(?: ones?)? nor (?:the )?"
        r"(\w+)(?: ones?)?\b",
        third,
        text,
    )
    # ... and as one negation of two places ("the drawer that isn't at the top or at the bottom", "... not the top
    # or the middle one")
    text = re.sub(
        r"\s*,?\s*(?:(?:that|which) (?:is|are) not |(?:that|which) (?:isn't|aren't) |not )(?:at |in |on )?(?:the )?"
        r"(\w+)(?: ones?)?,? (?:or|nor) (?:at |in |on )?(?:the )?(\w+)(?: ones?)?\b",
        third,
        text,
    )
    # the same said as two negations in a row ("a drawer - not the top one, not the middle one")
    return re.sub(
        r"\s*(?:,|-+|:)?\s*(?:but )?(?:(?:that|which) (?:is|are) )?not (?:the )?(\w+)(?: ones?)?\s*"
        r"(?:,\s*(?:and |or )?|and |or |nor )(?:also )?(?:(?:is|are) )?not "
        r"(?:the )?(\w+)(?: ones?)?\b",
        third,
        text,
    )


def bare_rank(phrase: str) -> str | None:
    """The kind a rank said without a side counts among ("second plate" -> "plate"; not "second leftmost bowl",
    which counts from the left): the scene must hold that many of it. None for any other phrase."""
    first, _, rest = phrase.partition(" ")
    if RANKS.get(first, 1) < 2 or not rest or rest.split()[0] in _QUALIFIER_WORDS:
        return None
    return rest
