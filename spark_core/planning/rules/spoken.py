"""What is said in passing, said plainly (discourse.restructured's first step): a count in parentheses, tags and
words of address, remarks before and after the request, "the X one of the two Ys", "make X go into Y", the side an
ordinal counts from said apart from it, "that <kind>" for the one named before, a narrower kind before a wider word,
what is ruled out said first. Each is a rewrite of the lower-cased text into a form the parser reads; none drops a
word that names a thing the request acts on."""

from __future__ import annotations

import re

from ...perception.variants import KIND_OF
from .mentions import ATTRIBUTES
from .phrases import singular
from .things import is_thing, is_verb


def spoken(text: str) -> str:
    """`text` (lower-cased) with what is said in passing said plainly (see the module's docstring); each rewrite's
    comment names the wording it reads."""
    # "the right-hand bowl (of the two)": how many there are says nothing of which
    out = re.sub(
        r"\s*\(\s*of (?:the|those|these) (?:two|2|both)\s*\)|,? of the two(?=\s*(?:,|$|into|onto)\b)", "", text
    )
    # "pick up the block - not the blue one, the other one": the block that is not blue
    out = re.sub(
        r"\bthe ((?:\w+ )?\w+)\s*(?:,|-+)?\s*not the (\w+) one,? (?:but )?the other(?: one)?\b",
        r"the \1 that is not \2",
        out,
    )
    # a goal ruled out, said after the goal ("..., red must not end up in yellow", "red on blue. NOT blue on red,
    # ok?"): no step of its own (the goal said already stands); the thing it names must still be there
    out = re.sub(
        r",?\s*(?:the )?((?:\w+ )?\w+) (?:must|should|may|can)(?: not|n't|not) (?:end up|go|be put|be placed|be|land) "
        r"(?:on|in|into|onto|inside|on top of) (?:the )?(?:\w+ )?\w+(?=\s*(?:[.;!?]|$))",
        r". there is the \1",
        out,
    )
    if re.search(r"\b(?:on|in|into|onto|on top of)\b.*[.;!?] (?:not|never) ", out):
        out = re.sub(
            r"(?<=[.;!?]) (?:not|never) (?:the )?(?!(?:\w+ )?ones?\b)((?:\w+ ){0,2}?\w+) (?:on|in|into|onto|on top of) "
            r"(?:the )?(?:\w+ )?\w+(?:,?\s*(?:ok|okay|right|alright|got it|yeah)\b)?\s*(?:[.;!?]|$)",
            r" there is the \1.",
            out,
        )
    # a tag asking for assent ("there's a cabinet on the left, yeah? slide its drawer open", "that bowl, yeah, put
    # it ..."): no part of the request
    out = re.sub(r",?\s*\b(?:yeah|yep|yup|ok|okay|alright|you know|got it|see)\s*\?\s*(?=\S)", ". ", out)
    out = re.sub(r",\s*(?:yeah|yep|yup|you know)\s*,", ",", out)
    # "the right-hand one of the two black bowls": the right-hand black bowl
    out = re.sub(
        r"\bthe ((?:[\w-]+ ){1,2}?)one of (?:the |those |these )?(?:two |three |2 |3 )?((?:[a-z]+ )??)([a-z]+s)\b"
        r"(?=\s*(?:$|[,.;:!?-]|(?:goes|go|belongs?|should|must|needs?|is|are|has|and|then|in|into|on|onto|to|from|"
        r"over|inside|off|out|up|down|please|that|which|with|by|near|next|beside|first)\b))",
        lambda m: f"the {m.group(1)}{m.group(2)}{singular(m.group(3))}",
        out,
    )
    # "put it in there, in the drawer i mean": the place said again, by name
    out = re.sub(
        r"\b(in|into|on|onto|inside) (?:there|here)\s*,\s*((?:in|into|inside|on|onto|on top of) (?:the|that) "
        r"[a-z ]+?)(?:,? i mean)?(?=\s*(?:[.;!?]|$))",
        r"\2",
        out,
    )
    # "and then, no wait, after that the red one ...": a correction said only as a pause before the next step
    out = re.sub(
        r",?\s*\b(?:no,? wait|wait|hmm|um|uh|er)\s*,\s*(?=(?:after that|then|next|afterwards|and then)\b)", " ", out
    )
    # "the cabinet that stands close to you on the right": the cabinet that is on the right
    out = re.sub(
        r"\bthat (?:stands|sits|is|lies|rests)(?: (?:close|closest|near|nearest|next) to (?:you|me|the robot))? "
        r"(on the (?:left|right)|in (?:the )?(?:front|back))\b",
        r"that is \1",
        out,
    )
    # "open the drawer ... put the cube in the open drawer": the one opened before, whatever else is open
    out = re.sub(
        r"\bthe (?:now )?(?:open|opened) ([a-z]+)\b",
        lambda m: (
            f"the {m.group(1)}"
            if re.search(rf"\b(?:open|pull|slide|yank|draw)\b.*\b{m.group(1)}\b", out[: m.start()])
            else m.group(0)
        ),
        out,
    )
    out = _narrower_named(_that_kind(out))
    # a word of address ("see the sponge, sweetie?", "the bottle, buddy") and a word of praise said as a sentence
    # ("good. now stand it up ...") are no part of the request
    out = re.sub(rf",\s*\b(?:{_ADDRESS})\b(?=\s*(?:[?.!,;]|$))", "", out)
    # "..., by the way", "... - we're behind schedule already": a remark after the request
    out = re.sub(r"\s*(?:-+|,|;|\.)\s*[^-,;.]*?,?\s*\bby the way\s*[.!]?$", "", out)
    out = re.sub(
        r"(?<=\S)\s*(?:,|;|-+|\.)\s*(?:we|i)(?: are|'re|'m| am) (?:already )?(?:behind|late|running late|in a "
        r"hurry|short on time|pressed for time)\b[^.;!?]*[.!]?$",
        "",
        out,
    )
    out = re.sub(
        r"(?:^|(?<=[.!?;] ))(?:good|great|nice|perfect|lovely|excellent|well done|do it|execute|proceed|go ahead|"
        r"engage|make it so|go)\s*(?:[.!;]\s*|$)",
        "",
        out,
    ).strip()
    # "..., i want red on green. fix the stack.": asking for the goal just stated, in a word
    out = re.sub(
        r"(?<=[.!?;]) (?:fix|sort out|correct|redo|fix up) (?:the stack|the tower|it|that|this)\s*[.!]?$", "", out
    )
    # what the speakers are doing, said as a sentence before the request ("we're checking the scene before the demo;
    # could you ...")
    out = re.sub(
        r"^(?:(?:hi|hello|morning|good morning|hey|okay|ok|so|right)[,.!]*\s+)*(?:we|i)(?: are|'re|'m| am) "
        r"(?:[a-z]+ing)\b[^.;!?]*?[.;!?]\s+(?=(?:could|can|would|will|please|now)\b)",
        "",
        out,
    )
    # "the green cube closer in", "the bowl farther out": the nearer, the farther one
    out = re.sub(r"\bthe ((?:[a-z]+ ){0,2}(?!one\b)[a-z]+) (closer|nearer) in\b", r"the nearer \1", out)
    out = re.sub(r"\bthe ((?:[a-z]+ ){0,2}(?!one\b)[a-z]+) (?:farther|further) (?:out|back)\b", r"the farther \1", out)
    # "nearer the plate than the other one (is)": the comparison says no more than "nearer the plate"
    out = re.sub(r"\s+than the other(?: one| ones| bowl| two)?(?: is| does| are)?\b", "", out)
    out = _counted_from(out)
    # "rather than green on red, i want red on green", "not on top of the cabinet - the bottle goes in the bowl": what
    # is not meant, said first, is said after the request as any contrast
    out = re.sub(
        r"^((?:rather than|instead of|not (?=(?:on|in|into|onto|on top of|inside|next to|by|in front of|under)\b))"
        r"[^,;:-]+?)\s*(?:,|;|:|\s-+)\s*([^.;!?]+?)\s*([.;!?].*)?$",
        lambda m: _said_after(m.group(1), m.group(2), m.group(3) or ""),
        out,
    )
    # "not the bowl next to the plate; the one by the ramekin goes on it", "not the bowl on the ramekin but the other
    # one: put it ...": the thing ruled out first, then the one meant
    out = re.sub(
        rf"^not (?:the|a) ((?:(?!{_LOCATING}\b)[a-z]+ ){{0,2}}?[a-z]+) (?:that is |which is )?(({_LOCATING}) [^,;:]+?)"
        rf"\s*(?:,|;|:|\s-+)?\s*(?:but )?the (other )?one\b",
        _other_than_ruled_out,
        out,
    )
    # "you take the sponge, then you wipe the plate": the steps said to the robot as what it does
    out = re.sub(
        r"(?:^|(?<=[.;,!?:] )|(?<=\bthen )|(?<=\band ))you (?=([a-z]+)\b)",
        lambda m: "" if is_verb(m.group(1)) and m.group(1) not in ("know", "see", "mean", "are", "can") else m.group(0),
        out,
    )
    # "then with it you make the plate clean": the tool said before the step it is used in
    out = re.sub(
        r"\bwith (it|this|that|them) (?:you )?(([a-z]+)\b[^,.;!?]*)",
        # ("with that sponge": "sponge" names the tool, whatever else it may be)
        lambda m: f"{m.group(2).strip()} with {m.group(1)}" if _tool_first(m) else m.group(0),
        out,
    )
    # "... clean by rubbing hard": how a thing is cleaned, said of a cleaning already asked for
    out = re.sub(
        r",?\s*\bby (?:rubbing|scrubbing|wiping|scouring|polishing)(?: (?:it|them|hard|firmly|gently|lightly|well|"
        r"thoroughly|back and forth|around|a bit))*(?=\s*(?:[,.;!?]|$|with\b))",
        "",
        out,
    )
    # "make the plate clean", "get the tray spotless": clean it
    out = re.sub(r"\b(?:make|get) ((?:the|that|this) [a-z ]+?) (?:clean|spotless|shiny|sparkling)\b", r"clean \1", out)
    # "set the cube down inside the drawer": "down" of setting a thing down, not a word of the thing
    out = re.sub(
        r"\b(set|put|place|lay|lower|drop) ((?:the|that|this) [a-z ]+?|it|them) down "
        r"(?=(?:in|into|inside|on|onto|on top of|next to|beside)\b)",
        r"\1 \2 ",
        out,
    )
    # "the third drawer down": counted from the top
    out = re.sub(
        r"\bthe (first|second|third|1st|2nd|3rd) ((?:[a-z]+ )?(?:drawer|shelf|tier|rack|level))s? down\b",
        r"the \1 \2 from the top",
        out,
    )
    # "slide out the top drawer": the drawer slid out (open)
    out = re.sub(
        r"\b(slide|pull|draw) out ((?:the|its|their|that|this) [a-z' ]+?)(?=\s*(?:[,;.!]|and\b|$))", r"\1 \2 out", out
    )
    # "make the beads go from the cup into the bowl", "get the block to end up on the plate": the thing moved there
    out = re.sub(
        r"\b(?:make|have|let|get) ((?:the|that|this|those|these|all the) [a-z' -]+?) (?:to )?(?:go|move|end up|"
        r"wind up|travel|land)(?= (?:from|out of|into|in|onto|on|on top of|inside|over)\b)",
        r"put \1",
        out,
    )
    # "the more distant one": the farther one, for the one said before to name its kind
    out = re.sub(r"\bthe (?:more|most) (?:distant|remote)\b", "the farther", out)
    # "two black bowls there. grab the farther one": things counted, said without a verb, then one of them
    out = re.sub(r"^((?:two|three|2|3) [a-z ]+?) (?:there|here|on the table)\s*[.;:!]\s+", r"there are \1. ", out)
    # "it's meant to go in the bowl": where it should go
    out = re.sub(
        r"\b(it|they)(?: is|'s| are|'re) (?:meant|supposed) to (?=go |be (?:in|on|inside|on top of)\b)",
        r"\1 should ",
        out,
    )
    return out


# Words a speaker addresses the robot by.
_ADDRESS = r"sweetie|sweetheart|kiddo|buddy|pal|mate|dear|honey|champ|my friend"
# Where counting starts, and the side an ordinal counts from.
_COUNTED_FROM = {"robot": "front", "you": "front", "me": "front", "front": "front", "near side": "front"}
_COUNTED_FROM |= {"right": "right", "left": "left", "back": "back", "far side": "back"}


# Words that say where a thing is, after its kind ("the bowl next to the plate").
_LOCATING = r"(?:next to|beside|by|near|on top of|on|in|inside|under|behind|in front of|at|to the (?:left|right) of)"


def _other_than_ruled_out(m: re.Match) -> str:
    """ "not the bowl on the ramekin, the one on the box": the one meant, with its kind; "..., the other one": the one
    the contrast does not name; "..., the other one by the kettle": left as said, for the contrast rules."""
    kind, ruled_out, other = m.group(1), m.group(2), m.group(4)
    if not other:
        return f"the {kind}"
    if re.match(rf"\s+{_LOCATING}\b", m.string[m.end() :]):
        return m.group(0)
    return f"the {kind} not {ruled_out}"


def _said_after(contrast: str, request: str, rest: str) -> str:
    """The request, then the contrast said before it; an action ruled out ("rather than turning the stove on")
    goes, once its thing names the request's "it"."""
    if re.match(r"(?:rather than|instead of) [a-z]+ing\b", contrast):
        return f"{_it_named(request, contrast)}{rest}"
    return f"{request}, {contrast}{rest}"


def _it_named(request: str, contrast: str) -> str:
    """ "rather than turning the stove on, turn it off": "it" of the request is the thing the contrast said first."""
    thing = re.search(r"\bthe ((?:[a-z]+ ){0,2}?[a-z]+)(?= (?:on|off|open|closed|in|into|onto|to|from)\b|$)", contrast)
    return re.sub(r"\bit\b", f"the {thing.group(1)}", request, count=1) if thing else request


def _counted_from(text: str) -> str:
    """ "the second black bowl, counting outward from the robot, ...", "going out from the robot, the second bowl
    ...", "the first one counting from the right": the ordinal counts from that side ("the second black bowl from
    the front")."""
    said = re.search(
        r",?\s*\b(?:counting|going|starting|working|moving|looking) (?:out |outward |outwards |away |in |inward )?"
        r"from (?:the )?(robot|you|me|front|near side|right|left|back|far side)(?:-hand)?(?: (?:edge|side|end))?"
        r"(?: of the table)?\s*,?",
        text,
    )
    if not said:
        return text
    side = _COUNTED_FROM[said.group(1)]
    # (said in a parenthesis, the parenthesis goes with it)
    rest = re.sub(r"\(\s*\)", "", text[: said.start()] + " " + text[said.end() :])
    ordinal = None
    # the last ordinal said before the count, else the first after it
    for m in re.finditer(r"\bthe (first|second|third|fourth|last|1st|2nd|3rd) ", rest):
        if m.start() >= said.start():
            ordinal = ordinal or m
            break
        ordinal = m
    if ordinal is None:
        return text
    words = re.match(
        r"(?:(?!(?:on|onto|into|in|to|goes|go|and|is|from|off)\b)[a-z][a-z-]* ?){0,3}", rest[ordinal.end() :]
    )
    noun_end = ordinal.end() + len(words.group(0).rstrip()) if words else ordinal.end()
    out = rest[:noun_end] + f" from the {side}" + rest[noun_end:]
    return re.sub(r"\s+", " ", re.sub(r"\s+([,.;!?])", r"\1", out)).strip()


# Words before a kind that say which one of it ("the top drawer", "the left bowl").
_WHICH_WORDS = frozenset(
    ["top", "bottom", "middle", "upper", "lower", "left", "right", "front", "back", "near", "far", "nearer"]
    + ["farther", "nearest", "farthest", "first", "second", "third", "last", "other", "centre", "center"]
)


def _that_kind(text: str) -> str:
    """ "open the top drawer, then put the bowl into that drawer": "that <kind>" is the one of that kind named
    before, with the words that named it."""

    def named(m: re.Match) -> str:
        kind = m.group(1)
        before = [
            said
            for said in re.findall(rf"\bthe ((?:[a-z-]+ ){{1,3}}){kind}\b", text[: m.start()])
            if all(w in ATTRIBUTES or w in _WHICH_WORDS or w.endswith("most") for w in said.split())
        ]
        return f"the {before[-1]}{kind}" if before and is_thing(kind) else m.group(0)

    return re.sub(r"\b(?<!not )(?:that|this|the same) ([a-z]+)\b(?! (?:is|was|sits|one)\b)", named, text)


def _narrower_named(text: str) -> str:
    """ "the ramekin dish", "the bowl dish": a noun of a narrower kind before a wider word of its kind names the
    thing; the wider word adds nothing (and would find every dish)."""

    def narrower(m: re.Match) -> str:
        first, second = KIND_OF.get(m.group(1)), KIND_OF.get(m.group(2))
        return m.group(1) if first and second and first < second else m.group(0)

    return re.sub(rf"\b([a-z]+) ({'|'.join(_WIDER)})\b", narrower, text)


# Words of a kind that other kind words name part of ("dish": a plate, a bowl, a ramekin).
_WIDER = sorted(w for w, k in KIND_OF.items() if any(o < k for o in KIND_OF.values()))


def _tool_first(m: re.Match) -> bool:
    """ "with it you clean ...": the word after "with it" starts a step; after "with that" it may name the tool."""
    word = m.group(3)
    return is_verb(word) and not (m.group(1) in ("this", "that") and is_thing(word))
