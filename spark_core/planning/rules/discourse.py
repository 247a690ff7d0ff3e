"""How the parts of an instruction relate, before any clause is read: the order the steps happen in, what is only
context, what is only contrast, and which earlier thing a back-reference names.

People say steps out of order ("before putting the block in the drawer, open it"; "put the blue block in the yellow
tray once the red block is in the green one"), describe the scene before asking ("the drawer is open - shut it";
"the green cube stays put; put the red cube on it"), add what is *not* meant after a complete request ("tip the
beads into the bowl, not back into the mug"), open with a header that names nothing ("two jobs: ..."), refer back
by list position ("red block and blue block: the former ..., the latter ..."), and state the goal as a cleft or as
the holder with its contents ("the orange juice is what should go into the basket"; "bowl with the red block in
it, that's what I want"). These are properties of discourse, not of any verb or object, so they are handled once,
here, for every wording: `restructured` returns the instruction said plainly, in the order the steps happen, each
step a clause the rule parser and the order-free reader already read. The planner and observe apply it alike.

Safety is unchanged: a thing the original names is still named (context and contrast become "there is X"
sentences, which only name a thing; the planner refuses when perception does not find it), and nothing is
re-ordered unless both parts read as steps (a known verb, or a goal said as "X is in/on Y")."""

from __future__ import annotations

import re
from functools import lru_cache

from lemminflect import getAllLemmas, getLemma

from ...perception.colors import BASE_COLOURS
from ...perception.lexicon.nouns import nouns
from .colloquial import plain_colloquial
from .endstate import end_state_framed
from .lexicon import VERBS
from .mentions import ATTRIBUTES
from .phrases import singular
from .rewrite import starts_with_verb
from .specs import spelled_out
from .spoken import spoken
from .steps import sequenced
from .things import adverb_only, is_thing, is_verb
from .transcript import unpunctuated

# A short noun phrase after its determiner: up to four words, none of them a preposition, conjunction or verb of
# state (what a back-reference can stand for).
_STOPS = (
    r"on|in|at|to|from|onto|into|inside|with|for|that|which|not|of|and|or|but|then|is|are|it|them|once|after|"
    r"before|when|so|until|near|by|beside|next|between|under|over|off"
)
_WORD = rf"(?!(?:{_STOPS})\b)[a-z][\w'-]*"
_NP = rf"(?:{_WORD} ){{0,3}}{_WORD}"
_DET = r"(?:the|a|an|that|this)"
# Steps of the planner's own, and the words of a goal said as where a thing is ("the red block is in the tray").
_GOAL_AS_STATE = re.compile(rf"^(?:{_DET} )?{_NP} (?:is|are) (?:now |already )?(?:in|inside|on|on top of|onto|into) ")
# A goal said as the thing and where it goes, with or without a verb ("the milk goes in the basket", "square nut onto
# the square peg").
_BARE_GOAL = re.compile(rf"^(?:{_DET} )?{_NP} (?:(?:goes|go|belongs?) )?(?:in|into|on|onto|on top of|inside|to) ")
# Current states a thing is described in before the request, and saying it is to stay as it is.
_STATES = r"(?:open|opened|closed|shut|on|off|empty|full|ajar|cold|hot|there|here|in the way|out)"
_STAYS = (
    r"(?:stays?|remains?|is staying|should stay|must stay|can stay|stays? where (?:it|they) (?:is|are)|remains? where "
    r"(?:it|they) (?:is|are))(?: put| still| in place| as (?:it|they) (?:is|are)|"
    r" (?:right |just |exactly )?where (?:it|they) (?:is|are))?"
)
_OPENABLE = frozenset(["drawer", "door", "lid", "cabinet", "cupboard", "box", "microwave", "oven", "fridge"])
_SWITCHED = frozenset(["stove", "burner", "hob", "cooktop", "knob", "dial", "light", "lamp", "tap", "faucet"])


@lru_cache(maxsize=1)
def _verb_forms() -> tuple[str, ...]:
    return tuple(sorted({f for forms in VERBS.values() for f in forms}, key=len, reverse=True))


@lru_cache(maxsize=1)
def _first_words() -> frozenset[str]:
    """The first word of each of the planner's verbs, said apart from the rest ("switch it on", "pull it open")."""
    return frozenset(f.split()[0] for f in _verb_forms() if " " in f)


def _starts_with_verb(clause: str) -> bool:
    return any(clause == f or clause.startswith(f + " ") for f in _verb_forms()) or (
        clause.split(" ", 1)[0] in _first_words()
    )


def _base_verb(clause: str) -> str:
    """ "putting the block in ..." / "you've opened the drawer" -> "put the block in ..." / "open the drawer"."""
    clause = re.sub(r"^(?:you(?:'ve| have| had)?|we(?:'ve| have)?|i(?:'ve| have)?) ", "", clause.strip())
    clause = re.sub(r"^(?:done|finished|finish) ", "", clause)
    first, _, rest = clause.partition(" ")
    if first.endswith(("ing", "ed")) and len(first) > 4:
        base = getLemma(first, upos="VERB")
        if base and base[0] != first:
            return f"{base[0]} {rest}".strip()
    return clause


def _is_step(clause: str) -> bool:
    """A clause that is a step the parser reads: a verb of the planner's, or a goal said as where a thing is; and
    it names a thing or says "it" ("when you get a sec" is no step)."""
    names = any(is_thing(p.split()[-1]) for p in _noun_phrases(clause)) or re.search(r"\b(?:it|them)\b", clause)
    return bool(names) and (_starts_with_verb(clause) or bool(_GOAL_AS_STATE.match(clause)))


def _noun_phrases(clause: str) -> list[str]:
    return [m.group(1) for m in re.finditer(rf"\b(?:the|a|an) ({_NP})", clause)]


def _antecedent(main: str, sub: str) -> str | None:
    """What "it" in `main` stands for, from the noun phrases of `sub` said with it: by what `main`'s verb can do
    with a thing (open or close something that opens, switch something that is switched), else the thing `sub`
    acts on (its first noun phrase)."""
    phrases = _noun_phrases(sub)
    if not phrases:
        return None
    verb = main.split(" ", 1)[0]
    if verb in ("open", "close", "shut") or re.match(
        r"^(?:pull|slide|push) (?:it|them) (?:open|out|shut|closed)", main
    ):
        fits = [p for p in phrases if p.split()[-1] in _OPENABLE]
    elif verb in ("turn", "switch", "flip", "flick"):
        fits = [p for p in phrases if p.split()[-1] in _SWITCHED]
    else:
        fits = phrases[:1]
    return fits[-1] if fits else None


def _with_antecedent(main: str, sub: str) -> str:
    """`main` with its "it" named from `sub` (said before it, and about to be said after it)."""
    if not re.search(r"\b(?:it|them)\b", main):
        return main
    who = _antecedent(main, sub)
    return re.sub(r"\b(?:it|them)\b", f"the {who}", main, count=1) if who else main


_STATE_STEP = {"open": "open", "opened": "open", "closed": "close", "shut": "close", "on": "turn on", "off": "turn off"}


def _as_step(clause: str) -> str:
    """A subordinate clause as the step it stands for: "putting X in Y" / "you've opened X" -> "put X in Y" /
    "open X"; "the drawer is open" (a state to bring about first) -> "open the drawer"."""
    clause = _base_verb(clause)
    m = re.fullmatch(
        rf"((?:{_DET} )?{_NP}) (?:is|are) (?:fully |all the way )?(open|opened|closed|shut|on|off)", clause
    )
    return f"{_STATE_STEP[m.group(2)]} {m.group(1)}" if m else clause


def _temporal(text: str) -> str:
    """Steps said out of order, put in the order they happen: "before X, Y" -> "Y, then X"; "after / once / as soon
    as X, Y" -> "X, then Y"; "Y once / after / as soon as X" -> "X, then Y"; "Y before X-ing" -> "Y, then X". Only
    when both parts read as steps. The part said first names what "it" in the other stands for."""
    m = re.fullmatch(
        r"(?:first(?:ly)?,? )?(?:before|prior to) (.+?)\s*,\s*(?:then |first )?(.+?)\s*(?:first)?\.?", text
    )
    if m:
        sub, main = _as_step(m.group(1)), m.group(2).strip()
        if _is_step(sub) and _is_step(main):
            return f"{_with_antecedent(main, sub)}, then {sub}"
    m = re.fullmatch(r"(?:after|once|as soon as|when) (.+?)\s*,\s*(?:then )?(.+?)\.?", text)
    if m:
        sub, main = _as_step(m.group(1)), m.group(2).strip()
        if _is_step(sub) and _is_step(main):
            return f"{_with_antecedent(sub, main)}, then {main}"
    m = re.fullmatch(r"(.+?),? (?:but )?(?:only )?(?:once|after|as soon as) (.+?)\.?", text)
    if m:
        main, sub = m.group(1).strip(), _as_step(m.group(2))
        if _is_step(sub) and _is_step(main):
            return f"{_with_antecedent(sub, main)}, then {main}"
    m = re.fullmatch(r"(.+?),? before (\w+ing\b.*?)\.?", text)
    if m:
        main, sub = m.group(1).strip(), _as_step(m.group(2))
        if _is_step(sub) and _is_step(main):
            return f"{main}, then {sub}"
    return text


def _context(text: str) -> str:
    """A description of how a thing is now, said before the request about it ("the drawer is open - shut it", "the
    stove is off, switch it on", "the green cube stays put; put the red cube on it"): no step, only the thing named
    ("there is the drawer"), so that a later "it" finds it and it must be in the scene."""
    m = re.fullmatch(
        rf"({_DET} )?({_NP}) (?:(?:is|are|'s) (?:currently |still |now |already )?{_STATES}|{_STAYS}|"
        rf"(?:should not|shouldn't|must not|mustn't|ought not to|is not supposed to|isn't supposed to) be {_STATES})\s*"
        r"(?:[,;:.!]|\s-+\s|\s\u2013\s|\s\u2014\s)\s*(.+)",
        text,
    )
    if not m or not is_thing(m.group(2).split()[-1]) or not _is_step(m.group(3).strip()):
        return text
    return f"there is the {m.group(2)}. {m.group(3).strip()}"


def _unwanted_now(text: str) -> str:
    """What the speaker does not want any more, said before the request ("i don't want the green cube on top
    anymore - the red one goes on top of the green one"): no step, only the thing named ("there is the ...")."""
    m = re.fullmatch(
        rf"(?:i|we) (?:do not|don't|dont) (?:want|like|need) {_DET} ({_NP})\b[^,;:.!-]*?"
        r"\s*(?:[,;:.!]|\s-+\s|\s\u2013\s|\s\u2014\s)\s*(.+)",
        text,
    )
    if not m or not is_thing(m.group(1).split()[-1]):
        return text
    rest = m.group(2).strip()
    if not (_is_step(rest) or " goes " in rest or " go " in rest):
        return text
    return f"there is the {m.group(1)}. {rest}"


def _counted_kind(text: str) -> str:
    """ "there are two black bowls. leave the far one and move the other one onto the plate", "two black bowls near
    the cabinet - i need the lower one ...": each "one" after a count of a kind is of that kind, and the count
    goes."""
    m = re.fullmatch(
        r"(?:there(?: are|'re| re|'s| is) )?(?:two|three|2|3) ([a-z ]+?)"
        r"(?: here| there| on the table| in front of you| (?:near|by|next to|beside|around) the [a-z ]+?"
        # where the two are ("two bowls over on the left", "two little boxes up front"): both, so no help choosing
        r"| (?:over |up |down |back )?(?:on|to|at|in) (?:the |your )?(?:left|right|front|back|rear)(?: side)?"
        r"| up front| in front| over there| over here)?"
        r"\s*(?:[,;:.!]|\s-+)\s*(.+)",
        text,
    )
    if not m or not m.group(1).endswith("s"):
        return text
    kind = " ".join([*m.group(1).split()[:-1], singular(m.group(1).split()[-1])])
    rest = re.sub(r"\b(the|that|this) ((?:\w+ )?)one\b", rf"\1 \2{kind}", m.group(2))
    return rest if rest != m.group(2) else text


def _one_of_count(text: str) -> str:
    """ "one of the two black bowls is sitting on the stove. pick that one up ...": the one of them said so is "the
    black bowl" (where it is says which)."""
    text = re.sub(
        r"\bone of the (?:two|three|2|3) ([a-z]+(?: [a-z]+)?)s\b(?= (?:is|that is|which is|sitting|standing|on|in)\b)",
        r"the \1",
        text,
    )
    # "one bowl is stacked on the ramekin. take it ...": one of a kind said with where it is
    return re.sub(
        r"(^|[.;!]\s+)one ([a-z]+(?: [a-z]+)?)(?= (?:is|sits|stands|rests) (?:stacked |sitting |standing |resting |"
        r"placed |located )?(?:on|in|inside|on top of|next to|beside)\b)",
        lambda m: f"{m.group(1)}the {m.group(2)}" if is_thing(m.group(2).split()[-1]) else m.group(0),
        text,
    )


def _chosen(text: str) -> str:
    """ "i want the black bowl up on top of the cabinet - take it and set it on the plate": the thing wanted, then
    acted on by "it", is chosen, not wished somewhere."""
    return re.sub(
        r"^(?:i want|i need|i would like|i'd like|i mean|i'm after|i am after) ((?:the|that) [a-z' ]+?)"
        r"\s*(?:[-:;,.]+)\s*"
        r"(?=(?:now )?(?:take|pick|grab|get|lift|move|put|set|place|bring) (?:it|that)\b)",
        r"there is \1. ",
        text,
    )


def _state_after(text: str) -> str:
    """A goal said as the thing (picked out by where it is now) and then where it ends up, or how it got there:
    "the black bowl that is on the stove, sitting on the plate" (a put); "i'd like the red block in the green area,
    pushed forward along the table" (a push)."""
    text = re.sub(
        r"^((?:the|a|an) [a-z ]+? (?:that|which) (?:is|are) (?:currently |now |still |presently )?"
        r"(?:on|in|inside|on top of|next to|near|by) [a-z ]+?),\s*"
        r"(?:sitting|resting|standing|placed|lying|now) (on|in|inside|on top of|onto|into) ([a-z ]+?)\s*[.!]?$",
        r"put \1 \2 \3",
        text,
    )
    text = re.sub(
        r"^(?:i'd like|i would like|i want|i need) ((?:the|a|an) [a-z ]+?) (?:in|into|inside) ((?:the|a|an) [a-z ]+?),?"
        r"\s*(?:pushed|slid|shoved|nudged)( forward| forwards| ahead)?(?: along the table| across the table)?\s*[.!]?$",
        r"push \1\3 into \2",
        text,
    )
    return text


def _other_after_contrast(text: str) -> str:
    """ "put a black bowl on the plate - not the one on the cabinet, the other one": the contrast says which; "the
    other one" after it adds nothing."""
    text = re.sub(
        r"(\s-+\s*not (?:the|that) (?:one|[a-z]+) [^,;.]+?),\s*(?:but |just )?the other (?:one|[a-z]+)\s*([.!]?)$",
        r"\1\2",
        text,
    )
    # ... and as a sentence of its own after the request ("put the black bowl on the plate. not the one up on the
    # cabinet, the other one"): the contrast after a comma, which the parser reads as the thing's qualifier
    return re.sub(
        r"(?<=\S)\s*[.;!]\s+(not (?:the|that) (?:one|[a-z]+) (?:up |down |over )?"
        r"(?:on|in|inside|on top of|next to|near|by|beside|at) [^,;.]+?),\s*(?:but |just |i mean )?"
        r"the other (?:one|[a-z]+)\s*([.!]?)$",
        r", \1\2",
        text,
    )


def _said_again(text: str) -> str:
    """ "ketchup in the basket. not the bbq sauce, the ketchup": a last sentence that rules a thing out and names
    again a thing the request named only says the request again; it goes."""
    m = re.search(rf"(?<=[.!?;])\s*not {_DET} {_NP},?\s*(?:but |i mean |just |only )?{_DET} ({_NP})\s*[.!]*$", text)
    if not m or not re.search(rf"\b{re.escape(m.group(1))}\b", text[: m.start()]):
        return text
    return text[: m.start()].strip()


def _apposed_contrast(text: str) -> str:
    """ "put the tomato sauce, not the bbq sauce, in the basket", "the red cup, not the blue one, goes on the tray":
    a thing ruled out between the thing and the rest of its clause is said after the clause, as a contrast is; a
    step after it ("..., and put ...") keeps it where it is. "Not the blue one" there says which of the thing's kind
    ("the cup that is not blue"), not which place, once it moves."""

    def after(m: re.Match) -> str:
        one = re.fullmatch(r"(?:not|rather than|instead of) \w+ (\w+) one", m.group(2))
        if one:
            return f"{m.group(1)} that is not {one.group(1)} {m.group(3)}{m.group(4)}"
        return f"{m.group(1)} {m.group(3)}, {m.group(2)}{m.group(4)}"

    return re.sub(
        rf"^(.*?\b{_DET} {_NP}),\s*((?:not|rather than|instead of) {_DET} [^,;.]+?),\s*"
        rf"((?:in|into|on|onto|to|inside|on top of|next to|over to|in front of|{_GOAL_VERBS})\b[^,.;]*?)([.!]?)$",
        after,
        text,
    )


def _contrast(text: str) -> str:
    """What is not meant, said after a complete request ("put the juice in the basket - not the ketchup and not the
    bbq sauce", "tip the beads into the bowl, not back into the mug", "..., rather than the plate"): no step; each
    thing it names is still named (a "there is" sentence before the request, so that it must be in the scene)."""
    m = re.fullmatch(
        r"(.+?)\s*(?:,|;|\s-+\s|\s\u2013\s|\s\u2014\s)\s*((?:(?:and |but )?(?:not|rather than|instead of) .+?)+)[.!]*",
        text,
    )
    if m and _same_request_reversed(m.group(2).removeprefix("but ").removeprefix("not "), m.group(1)):
        return m.group(1).strip()  # "stack red on green, not green on red": the request said the other way round
    if not m:
        return text
    said_as_goal = _GOAL_AS_STATE.match(m.group(1)) or _BARE_GOAL.match(m.group(1)) or " goes " in m.group(1)
    if not _is_step(m.group(1)) and not said_as_goal:
        return text
    main = m.group(1).strip()
    parts = re.split(r"\s*(?:,\s*)?(?:and |but )?(?:not|rather than|instead of)\s+", m.group(2))
    things = []
    for part in (p.strip() for p in parts if p.strip()):
        said = re.fullmatch(
            rf"(?:back |again )?(?:(?:in|into|onto|on|to|in front of|on top of|inside|from|out of) )?"
            rf"(?:(?:any|one) of )?(?:the|a|an|its|their) ({_NP})"
            r"(?: (?:on|in|at|to) (?:the|your|my) (?:left|right|back|front|middle|far end|near end|other side))?",
            part,
        )
        thing = said.group(1) if said else ""
        if thing.split()[-1:] in (["one"], ["ones"]):
            # "put the nut on the square peg - not the round one": one of the kind the request named last; "put the
            # near bowl on the plate, not the far one": of the kind said with the opposite word
            head = _opposed_thing(thing.split()[0], main) or _last_thing(main)
            if head and re.search(rf"\b(?:a|an|any|one) (?:\w+ )?{head}\b", main):
                return text  # "open a drawer - not the top one": which one it is, the parser's to read
            thing = " ".join([*thing.split()[:-1], head]) if head else ""
        if not thing or not is_thing(thing.split()[-1]):
            return text  # a contrast of how or where, not of which thing ("not too fast"): the parser's to read
        things.append(_singular_thing(thing) if re.search(r"\b(?:any|one) of ", part) else thing)
    return "".join(f"there is the {t}. " for t in things) + main


def _same_request_reversed(part: str, main: str) -> bool:
    """ "green on red" after "stack red on green": two things and a relation, each thing named in the request."""
    said = re.fullmatch(rf"(?:the )?({_NP}) (?:on|onto|on top of|in|into|inside) (?:the )?({_NP})", part)
    if not said:
        return False
    words = set(re.findall(r"[a-z]+", main))
    return all(set(said.group(g).split()) <= words for g in (1, 2))


# Words said of one of two things, and the word said of the other.
_OPPOSED = {"near": "far", "nearer": "farther", "left": "right", "top": "bottom", "upper": "lower", "front": "back"}
_OPPOSED |= {"big": "small", "bigger": "smaller", "large": "little", "larger": "tinier"}
_OPPOSED |= {v: k for k, v in _OPPOSED.items()}


def _opposed_thing(word: str, text: str) -> str | None:
    """The thing `text` names with the word opposed to `word` ("far" -> "bowl" in "put the near black bowl on the
    plate")."""
    other = _OPPOSED.get(word)
    said = re.search(rf"\b{other} ((?:\w+ ){{0,2}}\w+)", text) if other else None
    head = None
    for w in said.group(1).split() if said else []:  # the last word of the run of nouns ("black bowl" -> "bowl")
        if not is_thing(w):
            break
        head = w
    return head


def _last_thing(text: str) -> str | None:
    """The last word of `text` that names a thing ("put the nut on the square peg" -> "peg")."""
    return next((w for w in reversed(re.findall(r"[a-z]+", text)) if is_thing(w) and w not in ("one", "ones")), None)


def _singular_thing(phrase: str) -> str:
    """ "drawers" -> "drawer": one of several, said in a contrast as "any of the drawers"."""
    *rest, head = phrase.split()
    lemma = getLemma(head, upos="NOUN")
    return " ".join([*rest, lemma[0] if lemma else head])


def _former_latter(text: str) -> str:
    """ "red block and blue block: the former into the green tray, the latter into the yellow one", "there's a green
    cube and a red cube. put the latter on the former": the last two things listed before "the former" / "the
    latter" are named again where those stand (the list said first, in any frame: "take ...", "there's ...")."""
    said = re.search(r"\bthe (?:former|latter)\b", text)
    if not said:
        return text
    pairs = [
        m
        for m in re.finditer(rf"(?:^|\b{_DET} )({_NP}) and (?:{_DET} )?({_NP})", text[: said.start()])
        if is_thing(m.group(1).split()[-1]) and is_thing(m.group(2).split()[-1])
    ]
    head = text[: said.start()]
    if pairs:
        pair = pairs[-1]
        # the words after the last article are the thing ("there's a green cube": green cube)
        first, second = (re.split(rf"\b{_DET} ", pair.group(g))[-1] for g in (1, 2))
        if pair.start() == 0 and re.fullmatch(r"\s*(?:[:,;]|\s-+\s)\s*", head[pair.end() :]) and first == pair.group(1):
            head = ""  # the list said as a header names nothing else: what follows is the request
    else:
        # "place the green block onto the blue block, then set the red block on top of the former": the two
        # things named last before it, each said once, in the order said
        named: list[str] = []
        # (said before the step that names the former or the latter)
        before = re.split(r"[,.;:!?]\s*(?:and )?(?:then )?|\s(?:and|then)\s", head)
        prior = " , ".join(before[:-1])
        for m in re.finditer(
            r"\b(?:the|a|an) ((?:[a-z]+ ){0,2}[a-z]+?)(?=\s*(?:$|[,.;:!?]|\b(?:on|onto|in|into|"
            r"and|then|to|from|off|out|inside|on top of|next to|beside)\b))",
            prior,
        ):
            if is_thing(m.group(1).split()[-1]) and m.group(1) not in named:
                named.append(m.group(1))
        if len(named) < 2:
            return text
        first, second = named[-2], named[-1]
    rest = re.sub(r"\bthe former\b", f"the {first}", text[said.start() :])
    return head + re.sub(r"\bthe latter\b", f"the {second}", rest)


def _header(text: str) -> str:
    """A header before a colon that names no thing and asks nothing ("two jobs: ...", "here's the plan: ..."):
    what follows is the request."""
    m = re.fullmatch(r"([a-z' ]{1,40}?)\s*(?:[:=]|-+>|=>|\u2192)\s*(.+)", text)  # "goal = ...", "target state -> ..."
    if not m or _starts_with_verb(m.group(1)):
        return text
    words = re.findall(r"[a-z]+", m.group(1))
    numbers = ("s", "here", "there", "one", "two", "three", "four", "five", "couple")
    # what a request is made of ("two stacking moves: ...", "three steps: ...")
    parts = {"move", "moves", "step", "steps", "job", "jobs", "task", "tasks", "thing", "things", "stage", "stages"}
    parts |= {"stacking", "action", "actions", "sequence", "order"}
    # what the request describes ("final configuration: ...", "end state: ...", "final state i'm after: ...")
    parts |= {"configuration", "state", "arrangement", "layout", "goal", "target", "result", "final", "end", "setup"}
    parts |= {"config", "cfg", "conf"}
    # the run it is for, or what the line is ("eval: ...", "episode 3: ...", "cmd: ...")
    parts |= {"eval", "evaluation", "episode", "ep", "trial", "run", "demo", "test", "cmd", "command", "instruction"}
    parts |= {"request", "todo", "note", "next", "new", "ok", "okay", "placement", "card", "spec", "wanted", "wish"}
    parts |= {"i", "am", "m", "we", "are", "re", "after", "want", "what", "looking", "for", "desired", "wanted"}
    if words[:1] in (["final"], ["end"], ["target"], ["desired"]):
        parts |= {"table", "scene", "picture", "look", "tabletop"}  # "final table: ...": how the scene should look
    if not words or any(is_thing(w) for w in words if w not in numbers and w not in parts):
        return text
    return m.group(2)


def _present_goal(text: str) -> str:
    """ "the bowl from the top of the cabinet sits on the plate", said alone: a goal said in the present is the goal
    (said before a request, "the bowl sits on the plate. put it in the basket", it says where the bowl is)."""
    return re.sub(
        # (a modal before the verb says the goal already: "the block should sit in the bowl")
        r"^((?:the|a|an) (?:(?!\b(?:that|which|who|should|must|ought|to|will|would|can|could|may|might|shall|needs?|"
        r"has|have|is|are|does|do)\b)[a-z' ])+?) (?:sits|rests|sit|rest|lies|stands) "
        r"((?:on|in|inside|on top of|onto|into) (?:the|a|an) [a-z']+(?: [a-z']+){0,2})\s*[.!]*$",
        r"\1 should sit \2",
        text,
    )


def _cleft(text: str) -> str:
    """A goal said as a cleft ("the orange juice is what should go into the basket", "the red block is the one that
    goes on the plate", "it's the butter that goes ..."), the goal and then that it is wanted ("ketchup in the basket
    is what i'm after"), or as the holder with what it should hold ("bowl with the red block in it, that's what I
    want"): said plainly."""
    text = re.sub(
        r"\s*[,;-]?\s*(?:that's|that is|this is|thats) (?:what|all) (?:i|we) (?:want|need|would like|'d like|am after"
        r"|'m after|are after)\.?$",
        "",
        text,
    )
    text = re.sub(
        rf"^((?:{_DET} )?{_NP}) (?:is|are) (?:what|the (?:one|ones|thing|things)(?: that)?) "
        r"(?=(?:should|must|needs? to|has to|have to|goes|go|belongs?|is to|are to|ought to)\b)",
        r"\1 ",
        text,
    )
    # "it's the butter that goes in the basket": the thing it singles out, then its goal
    text = re.sub(
        rf"\bit(?:'s| is) ((?:{_DET} )?{_NP}) (?:that|which) "
        r"(?=(?:goes|belongs|should go|needs to go|has to go|must go|gets put|is going)\b)",
        r"\1 ",
        text,
    )
    # "it's the salad dressing i want in the basket": the wish itself
    text = re.sub(
        rf"\bit(?:'s| is) ((?:{_DET} )?{_NP}) (?:that |which )?(i|we) (want|need|would like|'d like) ",
        r"\2 \3 \1 ",
        text,
    )
    # "not the bowl in the middle, the other one, onto the plate please": the verb left out before the place
    text = re.sub(
        r"^(not (?:the|a|an) [^,]+),\s*(the other (?:one|[a-z]+)),\s*"
        r"(?=(?:onto|into|on to|on top of|in|on) (?:the|a|an)\b)",
        r"\1, put \2 ",
        text,
    )
    # "ketchup in the basket is what i'm after": the goal, then that it is what is wanted
    text = re.sub(
        r"^([a-z][a-z' ]+?) (?:is|are) (?:what (?:i|we)(?: am|'m| are|'re) after|"
        r"what (?:i|we) (?:want|need|would like)|"
        r"the (?:goal|idea|plan|aim))\s*(?=[.!]?$)",
        r"i want \1",
        text,
    )
    m = re.fullmatch(rf"(?:{_DET} )?({_NP}) with (?:the|a|an) ({_NP}) (in|on|inside|on top of) (?:it|them)\.?", text)
    if m and not re.search(r"\b(?:should|must|needs?|has|have|is|are|be)\b", m.group(1)):  # no state said of it
        return f"the {m.group(2)} {m.group(3)} the {m.group(1)}"
    return text


_OPPOSITE_STATE = {"on": "off", "off": "on", "open": "closed", "closed": "open", "shut": "open"}


def _negated_state(text: str) -> str:
    """A state said as the other one's negation ("make sure the stove isn't on", "the drawer is not closed"): the
    other state, which the readers know ("... the stove is off")."""
    return re.sub(
        r"\b(is|are|(?:should|must|would|will|shall|can|needs? to|has to) ?(?:not|n't) be) ?"
        r"(?:not|n't)? ?(?:left |kept |still )?(on|off|open|closed|shut)\b"
        r"(?! (?:the|a|an|top|its|your|my|this|that|to|of)\b)"
        r"(?: (?:yet|anymore|any more|any longer|now)\b)?",
        _state_said,
        text,
    )


def _state_said(m: re.Match) -> str:
    """ "is not on" -> "is off"; "should not be open" -> "should be closed"; "is on" as it was said."""
    said = m.group(0)
    if not re.search(r"\b(?:not|n't)\b|n't", said):
        return said
    verb = "is" if m.group(1) in ("is", "are") else re.sub(r" ?(?:not|n't) be$", " be", m.group(1))
    return f"{verb} {_OPPOSITE_STATE[m.group(2)]}"


def _of_all_the_things(text: str) -> str:
    """ "of all the groceries on the table, grab the one nearest to you": "the one" of things said only as a class
    is the item the qualifier picks out of everything there."""
    m = re.match(
        r"(?:out )?of all (?:the |these |those )?(?:groceries|items|things|objects|products|stuff|goods)"
        r"(?: (?:on the table|here|there|in front of you|you can see))?\s*[,:;-]\s*",
        text,
    )
    if not m:
        return text
    return re.sub(r"\bthe one\b", "the item", text[m.end() :], count=1)


def _restack(text: str) -> str:
    """ "take the green cube off (the red one), then put the red cube on top of it": the thing on top comes off so that
    the one under it goes on top: one step, the second ("it" is the thing taken off); the first is how it is done."""
    return re.sub(
        r"\b(?:take|lift|get|pull|move|pick) ((?:the|that) [a-z ]+?) off(?: (?:of )?(?:the|that) [a-z ]+?)?\s*[,;.]?\s*"
        r"(?:and )?(?:then )?((?:put|place|set|stack|pop) (?:the|that) [a-z ]+? (?:on top of|onto|on)) "
        r"(?:it|that one)\b",
        r"\2 \1",
        text,
    )


def _not_there_but(text: str) -> str:
    """ "don't put the wine bottle in the rack, it goes up on top of the cabinet": a place ruled out for a thing,
    then where "it" goes: the thing goes there (the place ruled out is no thing to act on)."""
    text = re.sub(
        r"^(?:do not|don't|dont|never) (?:put|place|set|stick|leave|move) ((?:the|a|an) [a-z' ]+?) "
        r"(?:in|into|on|onto|inside|on top of|next to|by|back in|back on) (?:the|a|an) [a-z' ]+?\s*[,;.:-]+\s*"
        r"(?:but |instead |rather )?(?:it|they) "
        r"(?=(?:goes|go|belongs|belong|should go|needs to go|has to go|must go)\b)",
        r"\1 ",
        text,
    )
    # "don't put the wine bottle in the rack; stand it on top of the cabinet instead": "it" is the thing ruled out
    # there, not the place
    return re.sub(
        r"^(?:do not|don't|dont|never) (?:put|place|set|stick|leave|move) ((?:the|a|an) [a-z' ]+?) "
        r"(?:in|into|on|onto|inside|on top of|next to|by|back in|back on) (?:the|a|an) [a-z' ]+?\s*[,;.:-]+\s*"
        r"(?:but |instead |rather |just )?([a-z]+(?: up| down)?) (?:it|them)\b",
        r"\2 \1",
        text,
    )


def _on_top_of_last(text: str) -> str:
    """ "put the green block on the blue one, then add the red block on top (to finish the stack)": "on top" alone,
    after a step that put a thing on another, is on top of that thing."""
    text = re.sub(
        r"\s*\bto (?:finish|complete|top off|end|cap) (?:the |your |this |our )?(?:stack|tower|pile)\b", "", text
    )
    # "..., then put the red block on top of that stack": the stack just made, topped by what was put last
    stack = re.search(
        r"\bon(?: top of)? (?:that|the|this|your) (?:stack|tower|pile)\b(?= *(?:$|[.,;!]|and\b|then\b))", text
    )
    if stack and re.search(r"\b(?:on|onto|on top of) (?:the|a|an)\b", text[: stack.start()]):
        text = f"{text[: stack.start()]}on top{text[stack.end() :]}"
    m = re.search(
        # (or a step said without its verb: "..., then the red block on top")
        r"\b(?:(?:put|place|set|add|stack|pop|drop|lay|goes|go|sits|belongs)\b|then (?=(?:the|a|an) ))[^.;,]*? on top"
        r"(?= *(?:$|[.,;!]|and\b|then\b|so\b))",
        text,
    )
    if not m or not re.search(r"\b(?:on|onto|on top of) (?:the|a|an)\b", text[: m.start()]):
        return text
    return f"{text[: m.end()]} of it{text[m.end() :]}"


def _first_said_last(text: str) -> str:
    """ "It's the cream cheese that goes in the drawer. Open the drawer first.": a later sentence that asks for a step
    "first" happens before the ones said before it."""
    said = [x.strip() for x in re.split(r"(?<=[.!?;])\s+", text) if x.strip()]
    for n, sentence in enumerate(said[1:], 1):
        m = re.fullmatch(
            r"(?:and |but |oh,? |oh and )?(.+?),?\s+(?:first|beforehand|before that|before anything else)"
            r"\s*([.!]?)",
            sentence,
        )
        if m and starts_with_verb(m.group(1)):
            rest = " ".join([*said[:n], *said[n + 1 :]])
            first = f"{_named_later(m.group(1), rest)}{m.group(2) or '.'}"
            return f"{first} {rest}"
    return text


def _named_later(sentence: str, rest: str) -> str:
    """ "open the drawer" moved before "... goes in the top drawer": the thing said by its kind alone is the one the
    later sentences name with words of its own, when they name exactly one of that kind (and not as ruled out)."""

    def named(m: re.Match) -> str:
        head = m.group(1)
        said = {
            n.group(1)
            for n in re.finditer(rf"(?<!\bnot )\bthe ((?:[a-z]+ ){{1,2}}){head}\b", rest)
            if not re.search(r"\b(?:other|same|one)\b", n.group(1))
        }
        return f"the {said.pop()}{head}" if len(said) == 1 else m.group(0)

    return re.sub(r"\bthe ([a-z]+)\b(?=\s*$|\s*[,.;!?]|\s+(?:and|then)\b)", named, sentence)


def _its_part(text: str) -> str:
    """ "see the brown cabinet? its drawer is closed. open it.": a part said as "its" after a sentence or clause that
    named the thing is that thing's part ("the cabinet drawer")."""
    # (or after a verb in a later sentence: "see the cabinet? close its drawer", the owner said in a sentence before;
    # never where to grip it: "by its handle")
    # "open the drawer on it": the same part, said after it
    text = re.sub(r"\bthe (drawer|handle|knob|door|lid|dial) (?:on|of) it\b(?! (?:and|too|as well))", r"its \1", text)
    m = re.search(r"(?:^|[.?!;]\s*|(?<!\bby )(?<=\s))its (drawer|handle|knob|door|lid|dial)\b", text)
    if not m:
        return text
    before = text[: m.start() + 1]
    if m.start() > 0 and m.group(0)[0] not in ".?!;":
        stops = [b.end() for b in re.finditer(r"[.?!;]", before)]
        if not stops:
            return text
        before = before[: stops[-1]]
    ends = r"(?=\s+(?:in|on|at|of|by|next|near|with|to|from|that|which|and|is|are)\b|\s*[?.!,;]|$)"
    named = [
        n.group(1).split()[-1] for n in re.finditer(rf"\b(?:the|a|an|that|this) ((?:\w+ ){{0,2}}?\w+){ends}", before)
    ]
    owner = next((w for w in reversed(named) if is_thing(w)), None)
    if owner is None:
        return text
    return text[: m.start()] + re.sub(r"its (\w+)", rf"the {owner} \1", text[m.start() :], count=1)


# Words after "but" that start a clause of their own: a negation, a verb or an adverb ("... on the plate but don't
# touch the bowl", "... but be gentle", "... but slowly"); a thing or a colour after it is what "but" sets apart
# ("all the blocks but the red one", "anything but blue").
_CLAUSE_AFTER_BUT = frozenset(["don't", "dont", "do", "never", "please", "just", "also", "then", "make", "try"])


def _but_clause(text: str) -> str:
    """ "A but B" where B starts a clause, said as after a comma ("A, but B"), as the clause splitter reads it."""

    def comma(m: re.Match) -> str:
        word = m.group(1)
        starts = word in _CLAUSE_AFTER_BUT or adverb_only(word) or (is_verb(word) and word not in ATTRIBUTES)
        return f", but {word}" if starts else m.group(0)

    return re.sub(r"(?<=[a-z]) but ([a-z']+)", comma, text)


def _named_in_apposition(text: str) -> str:
    """ "grab the item closest to the robot - the milk - and put it ...", "take whatever's nearest, the soup, and
    ...": a thing said only as an item, then named between dashes or commas, is the thing named."""
    return re.sub(
        r"(?:(?<!\bnot )\b(?:the|a|an) (?:[a-z]+ )?(?:item|thing|object|product|one)\b|\bwhatever(?:'s| is)?)"
        r"[^,;:()-]*?"
        r"\s*(?:,|\s-+|\()\s*"
        rf"((?:the|a|an) (?!(?:[a-z]+ )?ones?\b)[a-z ]+?)\s*(?:,|\s-+|\))\s*(?=(?:and|then|{_PLACE_PREPS})\b)",
        r"\1 ",
        text,
    )


# Words that say which of a stack or row a thing is: an ordinal or where it stands.
_WHICH_OF_A_ROW = (
    r"first|second|third|fourth|top|bottom|middle|lowest|highest|uppermost|lowermost|upper|lower|leftmost|rightmost"
)


def _row_restated(text: str) -> str:
    """ "open the lowest drawer of the cabinet, the third one down": an ordinal said again at the end, of a thing
    already picked out, says nothing new; "open the drawer, the third one down": it picks the thing out."""
    m = re.search(
        rf"\b(the|a) ((?:(?!the\b|a\b|of\b)[a-z]+ )*?[a-z]+(?: of the [a-z]+)?)\s*,\s*the ({_WHICH_OF_A_ROW}) one"
        r"((?: down| up| from the (?:top|bottom|left|right))?)"
        r"\s*[.!]?$",
        text,
    )
    if not m:
        return text
    thing = m.group(2)
    if re.search(rf"\b(?:{_WHICH_OF_A_ROW})\b", thing):
        return f"{text[: m.start()]}{m.group(1)} {thing}"
    noun, sep, of = thing.partition(" of ")
    return f"{text[: m.start()]}{m.group(1)} {m.group(3)} {noun}{m.group(4)}{' of ' + of if sep else ''}"


# Whose a thing is ("the stove's bowl"), not "that's" / "it's" (that is, it is).
_POSSESSIVE = r"\b(?!(?:that|it|what|there|here|who|which|where|he|she)'s)[a-z]+'s\b"


def _stage_direction(words: str) -> bool:
    """ "whispering", "quietly": how it is said, as a script writes it."""
    first = words.split()[0]
    return adverb_only(first) or (is_verb(first) and first.endswith("ing"))


def _manner_dropped(text: str) -> str:
    """ "quietly slide the drawer closed", "..., smartly now!": a word only ever an adverb, said of how the request
    is done, before its verb or alone after a comma at the sentence's end, says nothing of what is done."""
    text = re.sub(
        r"(^|\s)([a-z]+ly) (?=([a-z]+))",
        lambda m: m.group(1) if adverb_only(m.group(2)) and _starts_with_verb(text[m.end() :]) else m.group(0),
        text,
    )
    # a stage direction in parentheses ("(whispering)", "(quietly)") at the start or the end
    text = re.sub(
        r"(?:^\(\s*([a-z]+(?: [a-z]+)?)\s*\)\s*|\s*\(\s*([a-z]+(?: [a-z]+)?)\s*\)\s*(?=[.!?]*$))",
        lambda m: m.group(0) if not _stage_direction(m.group(1) or m.group(2)) else "",
        text,
    )
    # how it should lie where it goes ("..., leave it lying flat on the bottom"): the carry already puts it there
    text = re.sub(
        r"(?:,\s*|\s+and\s+)(?:then )?leave (?:it|them) (?:lying |sitting |standing |resting )?"
        r"(?:(?:flat|upright|level|the right way up)(?: (?:on|at) the bottom(?: of (?:it|them))?)?"
        r"|(?:on|at) the bottom(?: of (?:it|them))?)\s*(?=[.!?]*$)",
        "",
        text,
    )
    # a comparison says how, never what ("..., as one would handle a ming vase", "..., as if it were made of glass")
    text = re.sub(
        r",\s*(?:just )?(?:as (?:one|you|i|we|a \w+) (?:would|might|does|do)|as if|as though|like (?:one|you) would)\b"
        r"[^.!?;]*",
        "",
        text,
    )
    return re.sub(
        r",\s*(?:(?:very|so|extra|real|super|nice and) )?((?:[a-z]+ly )?[a-z]+ly)(?: now| please| there)?"
        r"\s*([.!?]*)\s*$",
        lambda m: m.group(2) if all(adverb_only(w) for w in m.group(1).split()) else m.group(0),
        text,
    )


def _pointed_and_urged(text: str) -> str:
    """ "ah go on, open that drawer there": urging said before the request ("go on,", "come on,") and "there" after
    a thing pointed at with "that" say nothing of what is done ("go on" as a goal, "it should go on the plate", is
    never said before a comma)."""
    text = re.sub(
        r"^(?:(?:ah|oh|well|now|aw) )?(?:go on|come on|go ahead|off you go)\s*[,!.]+\s*(?=(\S.*))",
        lambda m: "" if _starts_with_verb(m.group(1)) else m.group(0),
        text,
    )
    # (not where a carry puts it: "put that cup there" says where)
    return re.sub(
        r"\b(([a-z]+) (?:that|this|those|these) [a-z]+(?: [a-z]+)?) (?:there|here|over there)"
        r"(?=\s*,|\s+(?:and|then)\b)",
        lambda m: m.group(0) if m.group(2) in VERBS["put"] else m.group(1),
        text,
    )


# Where a thing is: a preposition and the thing it is on, in or by ("on the ramekin", "next to the plate").
_WHERE_PHRASE = r"(?:on top of|on|in|inside|next to|beside|by|near|under|behind|in front of) (?:the|a|an) [a-z' ]+?"
# Words that pick one thing out of its kind ("the closer one", "the left mug", "the second bowl").
_PICKING = (
    r"closer|nearer|closest|nearest|farther|further|farthest|furthest|left|right|leftmost|rightmost|front|back|"
    r"first|second|third|last|middle|top|bottom|higher|lower|highest|lowest|bigger|smaller|larger|taller|shorter"
)
# How a thing is said to rest where it is ("it's stacked on the ramekin").
_RESTING = r"(?:(?:stacked|sitting|resting|placed|lying|standing|set|sat|perched|parked) )?"


# Words that start a sentence and are no thing's first word.
_NOT_LEADS = frozenset(
    ["it", "this", "that", "there", "here", "what", "which", "who", "whatever", "whichever", "i", "we", "you", "they"]
    + ["he", "she", "everything", "something", "nothing", "all", "both", "each", "one", "none", "so", "and", "but"]
)


def _article_restored(text: str) -> str:
    """ "green cube is closer to you. put the red one on it", "middle drawer of the cabinet should be open": a sentence
    that starts with a thing said without its article, then says what it is or should be, is said of that thing."""

    def restored(m: re.Match) -> str:
        words = m.group(2).split()
        if words[0] in _NOT_LEADS or starts_with_verb(m.group(2)):
            return m.group(0)
        head = m.group(2).split(" of ")[0].split()[-1]
        return f"{m.group(1)}the {m.group(2)} " if is_thing(head) else m.group(0)

    return re.sub(
        r"(^|[.!?;]\s+)((?!(?:the|a|an|my|your|its|their|our|this|that|these|those)\b)[a-z]+(?: [a-z]+)?"
        r"(?: of the [a-z]+(?: [a-z]+)?)?) (?=(?:is|are|should|must|needs to|has to|ought to|sits|stands)\b)",
        restored,
        text,
    )


_INTO = {"on": "onto", "onto": "onto", "in": "into", "into": "into"}  # a place said without a verb: where it goes


def _located_first(text: str) -> str:
    """ "locate the white bowl and ensure the red block is placed inside it", "find the bowl next to the ramekin and
    set it on the plate", "look for the bowl by the box; once you have it, set it on the plate": a thing looked for
    first is named for what follows ("it"), not picked up. ("between the plate and the ramekin" is one place: its
    "and" joins no step.)"""
    text = re.sub(r"\b(between (?:the|a|an) [a-z]+(?: [a-z]+)?) and (?=(?:the|a|an) )", r"\1 &between ", text)
    return _LOOKED_FOR.sub(r"there is \1. ", text).replace(" &between ", " and ")


_LOOKED_FOR = re.compile(
    r"^(?:please )?(?:locate|find|spot|identify|look for|search for) ((?:the|a|an) [a-z'& ]+?)"
    r"(?:,? and (?:then )?|\s*[;.]\s*(?:(?:once|when|after) you(?:'ve| have)? (?:got|have|found|find|grabbed|grab|"
    r"spotted|spot|located|locate) (?:it|them),?\s*)?)(?=\S)"
)


def _pointed_then_described(text: str) -> str:
    """ "see the red mug? it has beads in it. pour them into the bowl": a thing pointed out, then what it holds said
    of "it", is that thing holding them ("the red mug has beads in it")."""
    return re.sub(
        r"^(?:there's|there is|see|look at|you see|notice|spot) (?:a|an|the) ([a-z ]+?)\s*[?.!,;]+\s*"
        r"(?:it|that one) (has|holds|contains|has got|'s got) ",
        r"the \1 \2 ",
        text,
    )


_NOW = r"(?:now|currently|still|at the moment|right now|at present|presently|for now)"


def _state_now(text: str) -> str:
    """ "..., it is closed now so open it first", "..., right now they are in the red mug": how things stand now is no
    step (a state said with "now" describes; "the drawer should be closed" asks)."""

    # "... inside the top drawer, it is closed now so open it first", "..., you'll have to pull the drawer open first i
    # think": advice to open the drawer a thing goes into (the planner opens a closed drawer it puts into)
    if re.search(r"\b(?:in|into|inside) (?:the |its |that )?[a-z' ]*drawer\b", text):
        text = re.sub(
            rf"\s*(?:[,;:]|\s-+)\s*(?:(?:but |and )?(?:it|the drawer|it's|its)(?: is| 's)? (?:{_NOW} )?(?:closed|shut)"
            rf"(?: {_NOW})?\s*[,;.]?\s*(?:so |and so |which means )?)?"
            r"(?:(?:you'?ll |you will |you'd |you |we'll |we )?(?:will )?(?:have|need|might need|may need|must) to |"
            r"please |just )?"
            r"(?:open|pull open|pull out|slide open|opening|pull|slide|get) (?:it|the drawer|the [a-z ]+ drawer)"
            r"(?: open| out| up)? "
            r"(?:first|beforehand|before that)\b(?: (?:obvs|obviously|i think|i guess|probably|of course))?"
            r"(?=\s*(?:$|[.!]))",
            "",
            text,
        )

    def described(m: re.Match) -> str:
        said = f"there is {m.group(1)}. " if m.group(1).startswith("the ") else ""
        return f"{'. ' if m.start() else ''}{said}"

    text = re.sub(
        rf",?\s*\b(it|they|the [a-z ]+?) (?:is|are|'s|'re) (?:{_NOW} (?:open|opened|closed|shut|empty|full|off|on)|"
        rf"(?:open|opened|closed|shut|empty|full|off|on) {_NOW})\s*[,;.]?\s*(?:so |and so |which means )?"
        r"(?=[a-z]+ (?:it|them|the)\b)",
        described,
        text,
    )
    # "right now green is on red, i want it the other way round, red on green": how it stands and that it should be
    # reversed, before the goal itself
    text = re.sub(
        rf"^(?:{_NOW}|as it stands|at the moment),? (?:the )?[a-z]+(?: cube| block)? (?:is|sits|'s) (?:on|on top of) "
        r"(?:the )?[a-z]+(?: cube| block| one)?\s*[,;.:-]+\s*(?:(?:and )?(?:i|we) (?:want|need|would like|'d like) "
        # (only with the wish that it be reversed: "now the red block is on the plate. put the blue one on it" names
        # what "it" is)
        r"(?:it|them|that|this) (?:the other way (?:round|around)|reversed|swapped|flipped)\s*[,;.:-]+\s*)(?=\S)",
        "",
        text,
    )
    return re.sub(
        rf",?\s*\b{_NOW},? (?:it|they) (?:is|are|'s|'re|sits?|rests?) (?:in|inside|on|on top of) (?:the|a|an) [a-z ]+?"
        r"(?=\s*(?:$|[.!]))",
        "",
        text,
    )


def _being_apposition(text: str) -> str:
    """ "..., the latter being the one closer to the robot", "...; the bowl in question being the one on top of the
    cabinet": which one a thing is, said after the request, is said right after that thing ("the green cube, the one
    closer to the robot"); a description under another noun ("the stove being the flat appliance on the right") only
    restates the thing and is dropped. Said in parentheses alike ("(the plate's the one on the box)")."""
    text = re.sub(
        r"\s*\(\s*(the [a-z ]+?|it)(?:'s| is) ((?:the|a|an) (?:one|item|thing|object) [a-z' ]+?)\s*\)\s*([.!]?)\s*$",
        r", \1 being \2\3",
        text,
    )
    m = re.search(
        r"\s*(?:[,;:-]+\s*(?:with )?(the former|the latter|it|the [a-z ]+?)(?: in question)? being |"
        r"[;.]\s*(the [a-z ]+?|it|that|this) (?:is|'s) (?=the (?:one|item|thing|object)\b))"
        r"((?:the|a|an) [a-z' ]+?)\s*([.!]?)\s*$",
        text,
    )
    if not m:
        return text
    head, subject = text[: m.start()], m.group(1) or m.group(2)
    what = re.sub(r"^the (?:item|thing|object)\b", "the one", m.group(3))
    if subject in ("that", "this"):
        subject = "it"
    named = [
        t
        for t in re.finditer(
            r"\bthe ((?:[a-z]+ ){0,2}[a-z]+?)(?=\s*(?:$|[,.;:!?]|\b(?:on|onto|in|into|to|and|then|"
            r"from|inside|on top of|next to)\b))",
            head,
        )
        if is_thing(t.group(1).split()[-1])
    ]
    if not named:
        return text
    if subject in ("the latter", "it"):
        at = named[-1]
    elif subject == "the former":
        at = named[-2] if len(named) > 1 else named[-1]
    else:
        noun = singular(subject.split()[-1])
        same = [t for t in named if singular(t.group(1).split()[-1]) == noun]
        if not same:
            return text
        at = same[0]
    if not re.match(r"the ones? ", what):
        return f"{head}{m.group(4)}"  # "the stove being the flat appliance ...": said again, nothing picked out
    tail = head[at.end() :]
    return f"{head[: at.end()]}, {what}{',' + tail if tail.strip() else ''}{m.group(4)}"


def _one_by_the_destination(text: str) -> str:
    """ "put the black bowl on the plate - the one that isn't between the ramekin and the plate": "the one ..." said
    after the destination names the destination itself, so it describes the thing carried (nothing is located by
    itself): said right after that thing."""
    m = re.fullmatch(
        r"(.*?\bthe ((?:[a-z]+ ){0,2}[a-z]+)) ((?:on|onto|in|into|inside|on top of|to) the (?:[a-z]+ ){0,2}([a-z]+))"
        r"\s*(?:,|\s-+)\s*(the one\b[^,;.!?]*?)\s*([.!]?)",
        text,
    )
    if not m or m.group(4) == m.group(2).split()[-1] or not re.search(rf"\bthe (?:[a-z]+ )?{m.group(4)}\b", m.group(5)):
        return text
    return f"{m.group(1)}, {m.group(5)}, {m.group(3)}{m.group(6)}"


def _ordinal_restated(text: str) -> str:
    """ "the second black bowl, the farther one from the robot, put it on the plate": "the second" said first, then
    which one it is; the one said second says it ("the black bowl farther from the robot")."""
    return re.sub(
        r"^the (?:second|other|2nd) ((?:[a-z]+ )?[a-z]+),\s*the ([a-z]+) one((?: (?:from|to) (?:the robot|you|me))?)"
        r"\s*,\s*",
        # (a colour before its noun: "the red mug")
        lambda m: (
            f"the {m.group(2)} {m.group(1)}, "
            if m.group(2) in BASE_COLOURS
            else f"the {m.group(1)} {m.group(2)}{m.group(3)}, "
        ),
        text,
    )


def _located_between_commas(text: str) -> str:
    """ "the higher bowl, up on the cabinet, put it on the plate": where a thing named first is, said between commas
    before the request that acts on it, says which one it is ("the higher bowl on the cabinet")."""
    return re.sub(
        r"((?:the|a|an) [a-z ]+?),\s*(?:up |down |over |right |sitting |standing |which is |that is |that's )?"
        r"((?:on|in|inside|on top of|next to|near|beside|by) (?:the|a|an) [a-z ]+?),\s*"
        r"(?=(?:take|put|place|move|grab|pick|lift|set|bring|get) (?:it|them)\b)",
        r"\1 \2, ",
        text,
    )


def _thing_header(text: str) -> str:
    """ "beads: from the mug to the bowl, pour em": a thing said as a header, then where it goes from and to, then the
    verb acting on it ("pour the beads from the mug to the bowl")."""
    return re.sub(
        r"^(?:the )?([a-z ]+?)\s*:\s*(from (?:the )?[a-z ]+? (?:to|into|onto) (?:the )?[a-z ]+?)\s*[,;-]+\s*"
        r"(?:just |please |then )?(pour|move|put|take|carry|tip|transfer|shift|bring) (?:em|'em|them|it)\s*([.!]?)$",
        # (poured "to" a container is poured into it)
        lambda m: (
            f"{m.group(3)} the {m.group(1)} "
            + (re.sub(r" to ", " into ", m.group(2)) if m.group(3) in ("pour", "tip") else m.group(2))
            + m.group(4)
        ),
        text,
    )


def _said_in_passing(text: str) -> str:
    """Things said in passing about the thing meant: a correction between dashes ("put the milk - no, the butter -
    in the basket"); where it is, between dashes or commas ("take the nearer bowl - it's stacked on the ramekin - and
    ...", "the higher of the two bowls, on top of the cabinet, onto the plate"); which one, counted from a side in a
    parenthesis ("the second one (counting from the left)"); that the goal is the end ("... = done")."""
    text = re.sub(r"\s*=+\s*(?:done|finished|complete|success|goal)\s*[.!]*$", "", text)
    # "the first of the cabinet's three drawers, counting from the top": the first drawer from the top
    text = re.sub(
        r"\bthe (first|second|third|fourth|last) of (?:the|its) (?:[a-z]+'s |[a-z]+ )?(?:two|three|four|five|[2-5]) "
        r"([a-z]+s)\b(?:,?\s*counting (?:from|down from|up from) the (top|bottom|left|right|front|back)\b,?)?",
        lambda m: f"the {m.group(1)} {singular(m.group(2))}" + (f" from the {m.group(3)}" if m.group(3) else ""),
        text,
    )
    # "..., pushed forward to get there": how the goal is reached, when the goal says where (the planner pushes
    # what it moves into a region)
    text = re.sub(
        r",\s*(?:by )?(?:pushed|pushing|slid|sliding|nudged|nudging|shoved|shoving)(?: it)?"
        r"(?: forward| forwards| along| across| over)? to get (?:it )?there\s*[.!]*$",
        "",
        text,
    )
    text = re.sub(
        r"\b(?:the|a|an) [a-z' ]+?\s+-+\s*(?:no|nope|sorry|wait|oops|er|erm|uh|scratch that)[,!]?\s*(?:i mean\s+)?"
        r"((?:the|a|an) [a-z' ]+?)\s*-+\s*",
        r"\1 ",
        text,
    )

    def aside(m: re.Match) -> str:
        # said of a thing a word already picks out ("the closer one, it's sitting on the tray,"): no more than an
        # aside; said of a thing by its kind alone, where it is picks it out
        picked = re.search(rf"\b(?:{_PICKING})\b[a-z ]*$", m.string[: m.start()])
        return " " if picked else f" {m.group(1)} "

    text = re.sub(
        rf"\s+-+\s*(?:it's|it is|that's|that is|which is|the one|one)\s+{_RESTING}({_WHERE_PHRASE})\s*-+\s*",
        aside,
        text,
    )
    text = re.sub(rf",\s*(?:it's|it is|which is|that's|that is)\s+{_RESTING}({_WHERE_PHRASE}),\s*", aside, text)
    text = re.sub(
        rf"(\b(?:the|a|an) [a-z' ]+?),\s*({_WHERE_PHRASE}),\s*(?=(?:onto|into|on|in|to|goes|go|should|and|then)\b)",
        r"\1 \2 ",
        text,
    )

    def counted(m: re.Match) -> str:
        before = m.string[: m.start()]
        ranked = re.search(r"\b(?:first|second|third|fourth|fifth|1st|2nd|3rd|4th|5th)\b(?: [a-z]+)?$", before)
        return f" from the {m.group(1)}" if ranked else ""

    return re.sub(
        r"\s*\(?\s*counting (?:from )?(?:the )?(left|right|front|back)"
        r"(?: to (?:the )?(?:left|right|front|back))?(?:\s*\))?",
        counted,
        text,
    )


_ORDINAL = r"first|second|third|fourth|fifth|1st|2nd|3rd|4th|5th"


def _ordinal_side_carried(text: str) -> str:
    """ "the first block from the left goes into the first tray from the left, second block into the second tray",
    "place the second cube from the front onto the first": an ordinal said again without its side counts from the
    side said first, and said without a noun ("the first", "the first one") is of the kind counted first."""
    m = re.search(rf"\b({_ORDINAL}) ([a-z]+) (?:counting )?from the (left|right|front|back|top|bottom)\b", text)
    if not m or not is_thing(m.group(2)):
        return text
    noun, side = m.group(2), m.group(3)
    out, last = [], 0
    for k in re.finditer(rf"\b({_ORDINAL})\b(?: ([a-z]+))?", text):
        said = k.group(2)
        after = text[k.end() :]
        if k.start() == m.start() or re.match(r" (?:counting )?from\b", after):
            continue  # the one counted, or one with its own side
        article = text[: k.start()].endswith("the ")
        if said in (None, "one", "ones") and article and not (said is None and re.match(r" [a-z]", after)):
            out += [text[last : k.start()], f"{k.group(1)} {noun} from the {side}"]
        elif said and is_thing(said) and (article or re.search(r"(?:^|[,;]\s*)$", text[: k.start()])):
            out += [text[last : k.start()], f"{k.group(1)} {said} from the {side}"]
        else:
            continue
        last = k.end()
    return "".join([*out, text[last:]])


def _wished(text: str) -> str:
    """A goal said as a wish or a remark about it: "it'd be great if the bowl ... ended up on the plate" (the bowl
    should end up on the plate); "i'd like the bowl that's stacked on the ramekin sitting on the plate instead";
    "the only bowl i want on the plate is the one on top of the cabinet"; "bowl by the ramekin, onto the plate:
    that's the target"; "the bowl currently resting on the box"; "reach up to the cabinet top, take the bowl from
    there"; "pushed right up to the front of the stove"."""
    text = re.sub(
        r"^(?:it'd|it would|that'd|that would|it will|it'll|i'd|i would) (?:be|find it|really be|honestly be) "
        r"(?:great|nice|good|ideal|perfect|lovely|awesome|helpful|brilliant|fantastic|grand|super) "
        r"if (.+?) (?:ended up|could end up|would end up|wound up|finished up|went|got|landed|were|was|sat|could be) ",
        r"\1 should end up ",
        text,
    )
    # a participle saying how the goal comes about, after it says where ("..., poured out of the mug"): where from
    text = re.sub(
        r"^(.+?) ((?:should|must|ought to|needs to|need to|has to) .+?),\s*(?:poured|tipped|emptied) (?:out of|from) "
        r"(the [a-z ]+?)\s*([.!]*)$",
        r"\1 from \3 \2\4",
        text,
    )
    # said in a wish: "sitting on" the place is on it; "that's stacked on" where it is now, "instead" no more
    text = re.sub(r"\b(?:that's|that is|which is) (?:stacked|sitting|resting|placed|lying|standing|perched) ", "", text)
    if re.match(r"(?:i'd like|i would like|i want|i'd love|i need|we want|we need) ", text):
        text = re.sub(
            r" (?:sitting|resting|standing|placed|lying|sat) (on|in|inside|on top of|onto|into) ", r" \1 ", text
        )
        text = re.sub(r",?\s*instead\s*([.!]*)$", r"\1", text)
    text = re.sub(
        r"^the only ([a-z ]+?) (?:i|we) (?:want|need|would like) (on|in|inside|on top of) (the [a-z ]+?) is the one "
        r"(?:(?:that is |that's |which is )?(?:sitting|resting|standing|placed|lying) )?"
        r"((?:on top of|on|in|inside|next to|beside|by|near) (?:the|a) [a-z ]+?)\s*([.!]*)$",
        r"put the \1 \4 \2 \3\5",
        text,
    )
    text = re.sub(
        r"\s*[:;,-]+\s*(?:that's|that is|this is|that'd be) (?:the|my|our) (?:target|goal|aim|plan|idea)\W*$", "", text
    )
    text = re.sub(
        r"\b(?:currently|presently|right now|at the moment|for now) (?=(?:sitting|resting|standing|lying|on|in)\b)",
        "",
        text,
    )
    text = re.sub(
        r"^reach (?:up |over |across |out )?(?:to|into|toward|towards) (the [a-z ]+?),\s*(take|grab|pick up|get|lift) "
        r"(the [a-z ]+?) (?:from|off) (?:there|it)\b",
        r"\2 \3 from \1",
        text,
    )
    return re.sub(
        # (not a side: "the bowl on the robot's right onto the plate")
        r"(?<!'s )(?<!the )(?<!your )(?<!my )(?<!its )(?<!far )\bright "
        r"(?=(?:up to|up against|next to|beside|by|into|onto|in front of|behind|over to)\b)",
        "",
        text,
    )


def _said_as_a_state(text: str) -> str:
    """The request said by the state it leaves or the order it restores: "get the drawer into an open position" opens
    it; "restack them so red sits on green" stacks red on green; "don't push the plate, push the cheese ..." names
    the plate (it must be there) and pushes the cheese; "the cabinet's top has a bowl on it; move that bowl ..." is the
    bowl on the cabinet's top. With them, what such a sentence says in passing: "which means opening it first" (the
    planner opens a drawer it puts into), "the table's centre", "the ramekin's neighbour, the bowl beside it", "not
    inside any drawer"."""
    text = re.sub(
        r"\b(?:get|put|bring|move|set|leave|place) ((?:the|a|an) [a-z' ]+?) (?:into|in|to) (?:an|the|its) "
        r"(open|opened|closed|shut) (?:position|state|configuration|config)\b",
        lambda m: f"{'open' if m.group(2).startswith('open') else 'close'} {m.group(1)}",
        text,
    )
    text = re.sub(
        r"\b(?:(?:re-?stack|stack|swap|rearrange|flip|reorder|reverse) (?:them|these|those|the (?:two|cubes|blocks|"
        r"pair|stack))|(?:i )?want (?:them|the (?:two|cubes|blocks|pair|stack)) (?:re-?stacked|swapped|rearranged|"
        r"flipped|reordered|reversed|the other way))"
        r"(?: up| around| round| over)?,? so (?:that )?(?:the )?([a-z]+(?: one| cube| block)?)(?: sits| is| ends up| "
        r"rests| goes|'s|s) on(?: top of)? (?:the )?([a-z]+(?: one| cube| block)?)\b",
        r"stack the \1 on the \2",
        text,
    )
    text = re.sub(
        r"^(?:do not|don't|dont|never) (\w+) ((?:the|a|an) [a-z' ]+?)\s*[,;]\s*(?:just |only |instead )?"
        r"\1 (?=(?:the|a|an) )",
        r"there is \2. \1 ",
        text,
    )
    # "..., which means opening it first": the planner opens a drawer it puts something in (planner.py)
    text = re.sub(
        r",?\s*(?:which|that|this) (?:means|requires|needs|involves) opening (?:it|the [a-z ]+?) (?:first|beforehand)",
        "",
        text,
    )
    # "the bowl at the table's centre": the centre of the table
    # (not "the cabinet's middle drawer", where "middle" says which drawer)
    text = re.sub(
        r"\bthe ([a-z]+)'s (centre|center|middle)"
        r"(?=\s*(?:$|[,.;:!?]|(?:goes|go|should|onto|into|on|in|to|and|then)\b))",
        r"the \2 of the \1",
        text,
    )
    # "the ramekin's neighbour, the black bowl right beside it,": the bowl next to the ramekin
    text = re.sub(
        r"\bthe ([a-z]+)'s neighbou?r\s*,\s*(the [a-z ]+?) (?:right |just |directly )?(?:beside|next to|by) it\s*,?",
        r"\2 next to the \1",
        text,
    )
    # "on top of the cabinet, not inside any drawer": where it is not to go, of no one thing, adds nothing
    text = re.sub(r",?\s*(?:and )?not (?:in|inside|into|on|onto) (?:any|a|one of the) [a-z]+\s*(?=$|[.!;])", "", text)
    return re.sub(
        r"^((?:the|a|an) [a-z' ]+?) (?:has|holds) (?:a|an|one) ([a-z ]+?) (?:on|on top of|in) it\s*(?=[;,.:-])",
        r"there's a \2 on \1",
        text,
    )


def _dashed_apposition(text: str) -> str:
    """ "take the bowl next to the ramekin - the closer of the two bowls - and ...", "pick up the cube on the right -
    the red one.": an apposition between dashes, or after one at the sentence's end, is one between commas; "the
    closer of the two bowls" is "the closer one"; "the one on the cabinet - that bowl - ..." names the one by where it
    is and its kind by the apposition: "the bowl on the cabinet ..."."""
    text = re.sub(
        r"\b(?:the|that) one ((?:on|in|at|by|near|next to|beside|under|inside|behind)\b[a-z' ]+?)\s+-+\s+"
        r"(?:that|this|the) ([a-z]+)\s+-+\s+",
        r"the \2 \1 ",
        text,
    )
    text = re.sub(r"\s+-+\s+((?:the|a|an) [a-z' ]+?)\s+-+\s+", r", \1, ", text)
    text = re.sub(
        r"\s+-+\s+((?:the|a|an) (?![a-z' ]*\b(?:in|into|on|onto|to)\b)[a-z' ]+?)\s*([.!?]*)$", r", \1\2", text
    )
    # (only in an apposition: "pick up the farther of the two cubes" names its kind)
    return re.sub(
        r"(?<=, )the (closer|nearer|farther|further|bigger|smaller|larger|taller|shorter|left|right|front|back) of the "
        r"(?:two|2|pair of) [a-z]+\b(?=,)",
        r"the \1 one",
        text,
    )


def _class_apposition(text: str) -> str:
    """ "put the chocolate pudding cup, the dessert, into the basket": an apposition whose one noun is a class the
    thing falls under (WordNet) only says what sort of thing it is."""

    def said(m: re.Match) -> str:
        thing, noun = m.group(2), m.group(3)
        lexicon = nouns()
        if any((k := lexicon.kinship(noun, w)) is not None and (k.broader or k.same) for w in thing.split()[-2:]):
            return f"{m.group(1)} {thing}" + ("" if m.group(4) == "," else m.group(4))
        return m.group(0)

    return re.sub(r"\b(the|a|an) ([a-z' ]+?), the ([a-z]+)((?:,|\s*[.!?]*$))", said, text)


def _restated_one(text: str) -> str:
    """ "take the stove's bowl, the black one sitting on top of it, and ...": an apposition said of a thing already
    picked out (by whose it is or where it is) only says it again; "take the bowl, the black one, and ...": its
    attribute joins the thing."""

    def said(m: re.Match) -> str:
        det, thing, attribute, rest = m.group(1), m.group(2), m.group(3).strip(), m.group(4).strip()
        ends, owned = m.group(5), re.search(_POSSESSIVE, thing)
        if re.search(r"\bnot\s*$", m.string[: m.start()]):
            return m.group(0)  # "not the middle drawer, the bottom one": a correction (qualify), no apposition
        # no other thing said in it (a side is none: "off to the right"), else the look may be of the thing after
        sides = re.sub(r"\b(?:to|on|at) (?:the|your|my) (?:left|right|front|back)\b", "", thing)
        alone = not re.search(r"\b(?:the|a|an|your|my|its)\b", sides)
        if attribute and not rest and not owned and alone:  # "the block that's farther from you, the red one"
            return f"{det} {attribute} {thing}{ends if ends is not None else ' '}"
        if ends is not None:
            return m.group(0)
        if owned or re.search(r"\b(?:on|in|inside|next to|near|by|beside|from|under)\b", thing):
            return f"{det} {thing} "
        # "the second bowl, the one on the stove": "second" only counted it as another of its kind; where it is says
        # which
        unordered = re.sub(r"^(?:second|2nd|other) (?=\w)", "", thing)
        if not attribute and re.fullmatch(_SAID_OF_PLACE, rest):  # "the milk, the carton closest to you, in ..."
            return f"{det} {unordered} {rest} "
        if not attribute and re.fullmatch(
            rf"(?:up |down |over |right |just )?(?:{_WHERE}) (?:the|your|my) [a-z ]+", rest
        ):
            # "the right bowl, the one in the middle of the table, goes ...": where it is joins the thing
            return f"{det} {unordered} {rest} "
        return m.group(0)

    # "1st bowl, the one closest to you, ...": an ordinal thing said first without its article (not "first, ...")
    text = re.sub(
        r"^(1st|2nd|3rd|first|second|third) ([a-z]+), (?=the (?:[a-z]+ )?one\b)",
        lambda m: (
            f"the {dict(zip(('1st', '2nd', '3rd'), ('first', 'second', 'third'))).get(m.group(1), m.group(1))} "
            f"{m.group(2)}, "
        ),
        text,
    )
    # "bowl closest to you, the one on the stove, onto the plate": a thing said first without its article (not a
    # request: "take the mug, the white one, ...")
    text = re.sub(
        r"^(?!(?:the|a|an|not|no|it|this|that|i|you|we|of|in|on|at|for|from|with|by|to|please|now|then|and|so|first|"
        r"next|after|once|when|if)\b)([a-z]+(?: [a-z]+){0,4}), (?=the (?:[a-z]+ )?one\b)",
        lambda m: m.group(0) if starts_with_verb(m.group(1)) else f"the {m.group(1)}, ",
        text,
    )
    # "the bowl on the cabinet, that one goes on the plate": "that one" only points back at the thing said first
    text = re.sub(
        rf"^((?:the|a|an) [a-z' ]+?),\s*(?:that|this) one (?=(?:{_GOAL_VERBS})\b)",
        r"\1 ",
        text,
    )
    # "take the bowl closest to you, beside the ramekin, and ...": where it is, said alone, as "the one beside ..."
    # ("sitting on the ramekin", "between the plate and the ramekin" alike)
    text = re.sub(
        rf"\b(the [a-z ]+?), (?:(?:sitting|standing|resting|lying|placed|located|kept) )?"
        rf"(?=(?:right |just |up |down |over )?(?:{_WHERE}|between) the [a-z ]+?, "
        rf"(?:and|then|{_GOAL_VERBS})\b)",
        r"\1, the one ",
        text,
    )
    return re.sub(
        rf"\b(the|a|an) ([a-z' ]+?)\s*,\s*the (?!other\b)((?:[a-z]+ )?)(?:one|{'|'.join(_GENERAL_NOUNS)})\b([^,;.!?]*)"
        rf"(?:,\s*(?=(?:and|then|{_PLACE_PREPS}|{_GOAL_VERBS})\b)|(\s*(?:[.!?]|$)))",
        said,
        text,
    )


# Where a thing goes, after it is named: an apposition before it ends at it.
_PLACE_PREPS = r"in|into|onto|on|inside|on top of|to|over to"
# What follows a thing named as the subject of its goal ("the milk goes in ...", "the cube should be on ...").
_GOAL_VERBS = r"goes|go|belongs?|should|needs? to|must|has to|is to|ends? up"
# Prepositions that say where a thing is.
_WHERE = r"in|on|on top of|inside|next to|near|by|beside|in front of|behind|at"
# The ordinal said for an item number counted from a side ("#2 from the left").
_ORDINAL_WORDS = ("first", "second", "third", "fourth", "fifth")
# Nouns that name a thing by what it is sold or kept in, or by nothing at all ("the milk, the carton nearest you").
_GENERAL_NOUNS = ("item", "thing", "object", "product", "carton", "box", "bottle", "jar", "can", "tin", "package")
# An apposition's words after its noun that only say where the thing is ("closest to you", "on the left").
_SAID_OF_PLACE = (
    r"(?:closest|nearest|furthest|farthest|leftmost|rightmost|frontmost|backmost)(?: (?:to )?(?:you|me|the robot|us))?"
    r"|on the (?:left|right)|in (?:the )?(?:front|back)"
)


# Words a speaker corrects what they just said with ("no wait", "sorry, i mean").
_CORRECTION = (
    r"(?:no,? wait|wait,? no|no,? no|no|sorry|oops|actually|make that|or rather|correction|scratch that|i mean|"
    r"i meant|er|erm|uh|um)"
)


# Words of one sort, one of which a correction swaps for another ("the left one, no, the right one").
_KINDS_OF_WORD = (
    frozenset(BASE_COLOURS),
    frozenset(["left", "right", "leftmost", "rightmost", "front", "back", "near", "far", "nearest", "farthest"])
    | frozenset(["top", "bottom", "middle", "upper", "lower", "first", "second", "third", "last", "closer", "further"]),
)


def _self_corrected(text: str) -> str:
    """ "put the red block in the bowl, sorry, i mean the blue block", "the left bowl ..., no wait, the right one",
    "put the red block, no, the blue block, in the bowl": the thing said after the correction replaces the one it
    corrects: the last one named of the same kind, else the last one named ("the right one" keeps its kind)."""
    m = re.search(
        rf"\s*(?:,|;|-+|\.\.\.)\s*(?:{_CORRECTION}\b\s*[,.]*\s*)+(?:the|a|an) ((?:[a-z]+ ){{0,2}})([a-z]+)"
        r"(?=\s*(?:$|[,.;!?]|\s(?:in|into|on|onto|to|and|then|from|off|please)\b))",
        text,
    )
    if not m:
        return text
    said, kind = m.group(1), m.group(2)
    before = text[: m.start()]
    named = [
        n
        for n in re.finditer(
            r"\b(?:the|a|an) ((?:[a-z]+ ){0,2})([a-z]+)(?=\s*(?:$|[,.;!?-]|\s(?:in|into|on|onto|to|and|then|from|off|"
            r"of|with|at|by|near|next|beside|please)\b))",
            before,
        )
        if n.group(2) == "one" or is_thing(n.group(2))
    ]
    if not named:
        return text
    if kind in ("one", "ones"):  # "the right one": the qualifier corrected, the kind kept
        words = set(said.split())
        kin = next((k for k in _KINDS_OF_WORD if words & k), frozenset())
        corrected = next(
            (n for n in reversed(named) if set(n.group(1).split()) & kin),
            next((n for n in reversed(named) if n.group(1)), named[0]),
        )
        new = f"the {said}{corrected.group(2)}"
    else:
        corrected = next((n for n in reversed(named) if n.group(2) == kind), named[-1])
        new = f"the {said}{kind}"
    after = text[m.end() :]
    if corrected.end() == len(before.rstrip()):  # "the red block, no, the blue block, in the bowl": one phrase
        after = re.sub(r"^\s*,\s*", " ", after)
        # "put the black bowl on the plate - the back one, no wait, the front one": the object said again, corrected
        said_of = re.fullmatch(
            r"(\w+(?: up)?) (?:the|a|an) ([a-z ]+?) ((?:in|into|on|onto|on top of|next to) (?:the|a|an) [a-z ]+?)"
            r"\s*(?:-+|,)\s*",
            before[: corrected.start()],
        )
        if corrected.group(2) == "one" and said_of and not after.strip(" .!"):
            return f"{said_of.group(1)} the {said}{said_of.group(2)} {said_of.group(3)}"
    return (before[: corrected.start()] + new + before[corrected.end() :] + after).strip()


# Words that take back what was just said (no hesitation sounds: "open the drawer, um, put the cube in it" is two
# steps); a bare "no" only after a pause mark.
_TAKEN_BACK = (
    r"(?:no,? wait|wait,? no|no,? no|sorry|oops|actually|make that|or rather|correction|scratch that|i mean|i meant)"
)
_TAKEN_BACK_RUN = re.compile(rf"(?:\s*(?:,|;|-+|\.)\s*(?:no\b[\s,.]*)?|\s+)((?:{_TAKEN_BACK}\b[\s,.]*)+)(?=\S)")
# The thing a request acts on: its first article phrase, up to where it goes or the clause ends.
_ACTED_ON = re.compile(
    r"\b((?:the|a|an) [a-z' ]+?)(?=\s*$|\s+(?:in|into|on|onto|on top of|to|from|off|next to|inside|over)\b)"
)


def _names_a_thing(word: str) -> bool:
    """A noun that may name a thing on the table: not a word of address or assent ("okay", "right", "buddy")."""
    lemmas = getAllLemmas(word)
    return is_thing(word) and "NOUN" in lemmas and "ADV" not in lemmas and not nouns().names_no_thing(word)


def _bare_topic(text: str) -> str:
    """ "middle drawer on the wooden cabinet, open it": a thing said first without its article, then a request that
    acts on "it", is the thing the request is about (as "the middle drawer ..., open it"), not a carry of it."""

    def topic(m: re.Match) -> str:
        said, request = m.group(2), m.group(3)
        head = re.split(rf" (?:{_WHERE}|of)\b", said, maxsplit=1)[0].split()
        if (
            re.match(
                r"(?:the|a|an|this|that|these|those|my|your|our|its|some|any|no|all|each|both|either|neither|none|"
                r"(?:any|every|some|no)(?:thing|one|body)|whatever|whichever)\b",
                said,
            )
            or not _names_a_thing(said.split()[0])
            and not getAllLemmas(said.split()[0]).keys() & {"ADJ", "NUM"}
            or (
                starts_with_verb(said)
                and not re.match(
                    r"[a-z]+ (?!(?:the|a|an|it|them|this|that|these|those|my|your|"
                    r"up|down|out|off|on|over|in|into|away|back|all|both|one|two|three|for)\b)[a-z]",
                    said,
                )
            )
            or not (starts_with_verb(request) or is_verb(request.split(" ", 1)[0]))
            or not re.match(r"\S+(?: up| out| down| on| off)? (?:it|them)\b", request)
            or not head
            or not _names_a_thing(head[-1])
        ):
            return m.group(0)
        return f"{m.group(1)}the {said}, {request}"

    return re.sub(r"(^|[.!?;]\s+)([a-z][a-z' ]*?)\s*,\s*([a-z][^.!?;]*)", topic, text)


# Labels a lab notebook puts before the thing a request is about ("sample: chocolate pudding. transfer ...").
_LABELS = r"(?:sample|specimen|item|object|payload|cargo|subject|article|unit under test)"


def _topic_carried(text: str) -> str:
    """ "the salad dressing, put inside the basket", "bowl on the stove. transfer to the plate.": a thing said first
    (with where it is, or after a label: "sample: chocolate pudding."), then a carry that says only where: the carry
    is of the thing ("put it inside the basket")."""
    verbs = "|".join(sorted((f for f in VERBS["put"] if " " not in f), key=len, reverse=True))
    text = re.sub(rf"^{_LABELS}\s*:\s*(?=[a-z' ]+[.!;]\s+(?:{verbs}) )", "", text)

    def carried(m: re.Match) -> str:
        thing = m.group(2)
        if starts_with_verb(thing) or re.search(r"(?<!that )(?<!which )\b(?:is|are|was|were|be)\b|'s\b", thing):
            return m.group(0)  # a request, or a remark about a thing, before the carry
        return f"{m.group(1)}{thing}, {m.group(4)} it "

    return re.sub(
        rf"(^|[.!?;]\s+|^(?:eh|ah|oh|so|ok|okay|now|right|well|alright),?\s+)"
        rf"((?:(the|a|an) )?[a-z' ]+?)(?:,|[.!:;])\s*({verbs}) "
        r"(?=(?:in|into|inside|on|onto|on top of|atop|to|over to)\s)",
        lambda m: carried(m) if m.group(3) or m.group(2).count(" ") < 6 else m.group(0),
        text,
    )


def _kindless_one(text: str) -> str:
    """ "the one on the stove, not the one up on the cabinet -> plate": "one" said first, of no kind named, is whatever
    is there (perception looks for a thing on the stove); another "one" ruled out by where it is adds nothing."""
    # (a thing, not a side: "the one on the left" of no kind named is any thing there, which says no kind)
    sides = r"(?!(?:left|right|front|back|rear|middle|end|far|near|top|bottom)\b)"
    where = rf"(?:on|in|inside|on top of|under|by|near|next to|beside|at) (?:the|a|an) {sides}[a-z' ]+?"
    m = re.match(
        rf"((?:take |grab |get |move |put |pick up )?)the one ({where})(?=\s*(?:[,:;.-]|->|$|\s+(?:goes|to|onto)\b))",
        text,
    )
    if not m:
        return text
    rest = text[m.end() :]
    rest = re.sub(rf"^\s*,\s*not the one (?:up |down )?{where}(?=\s*(?:[,:;.-]|->|$))", "", rest)
    return f"{m.group(1)}the thing {m.group(2)}{rest}"


def _located_topic_contrasted(text: str) -> str:
    """ "the bowl inside the top drawer, not the one on top of the cabinet: put it on the plate": a thing said first
    by where it is, then one of its kind ruled out: where it is picks it out already, the contrast adds nothing; said
    by its kind alone, the contrast is what picks it out ("the bowl that is not on the cabinet")."""
    where = r"(?:on|in|inside|on top of|under|by|near|next to|beside|between|at) (?:the|a|an) [a-z' ]+?"
    located = re.match(rf"((?:the|a|an) [a-z' ]+? {where})\s*,\s*not (?:the|that|this) [a-z' ]+?\s*[,:;.-]+\s*", text)
    if located and starts_with_verb(text[located.end() :]):
        return f"{located.group(1)}, {text[located.end() :]}"
    # said by a word that picks it out, then one of its kind ruled out ("the bottom drawer, not the top one - open
    # it"): the word picks it out already
    picked = re.match(
        r"((?:the|a|an) (?:[a-z']+ )+([a-z]+))\s*,\s*not (?:the|that|this) [a-z' ]+? ([a-z]+)\s*[,:;.-]+\s*", text
    )
    if picked and picked.group(3) in ("one", picked.group(2)) and starts_with_verb(text[picked.end() :]):
        return f"{picked.group(1)}, {text[picked.end() :]}"
    # said by its kind alone, one of its kind ruled out by a word ("the mug, not the blue one: put it ...")
    plain = re.match(r"((?:the|a|an) ([a-z]+))\s*,\s*not (?:the|that|this) ([a-z]+) ([a-z]+)\s*[,:;.-]+\s*", text)
    if plain and plain.group(4) in ("one", plain.group(2)) and starts_with_verb(text[plain.end() :]):
        return f"{plain.group(1)} that is not {plain.group(3)}, {text[plain.end() :]}"
    # said by its kind alone: the one ruled out by where it is ("the bowl, not the one on the cabinet: put it ...")
    kind = re.match(rf"((?:the|a|an) [a-z' ]+?)\s*,\s*not (?:the|that|this) ones? ({where})\s*[,:;.-]+\s*", text)
    if kind and starts_with_verb(text[kind.end() :]):
        return f"{kind.group(1)} that is not {kind.group(2)}, {text[kind.end() :]}"
    return text


def _destination_said_last(text: str) -> str:
    """ "not the butter - the cream cheese. basket": a thing said with no verb, then a sentence that is only a place
    for it: the thing and its place, as "the cream cheese, basket" is read."""
    m = re.fullmatch(r"([^.!?]+?)\s*[.!?]+\s+((?:(?:in|into|on|onto) )?(?:the |a |an )?([a-z]+))\s*[.!?]*", text)
    if not m or starts_with_verb(m.group(1)) or not is_thing(m.group(3)) or re.search(r"\bit\b", m.group(1)):
        return text
    return f"{m.group(1)}, {m.group(2)}"


def _asked_if_done(text: str) -> str:
    """ "is the pear in the bowl yet? if not, put it there": a question about the goal, then the request to make it
    so: the request is the goal asked about."""
    return re.sub(
        r"^(?:is|are) ((?:the|a|an) [a-z' ]+?) (in|inside|on|on top of|into|onto) ((?:the|a|an) [a-z' ]+?)"
        r"(?: yet| already| now)?\s*\?\s*(?:if not|no|otherwise|if it is not|if it isn't)\s*[,:-]?\s*"
        r"(?:please |just |then )?(put|place|move|set|get|pop) (?:it|them) (?:there|in there|on there)\s*([.!?]*)$",
        r"\4 \1 \2 \3\5",
        text,
    )


def _you_before_verb(text: str) -> str:
    """ "please you open the drawer", "you put the cup in the sink": a request said with its subject (a learner's
    order, or an order given to a person) is the request."""
    return re.sub(
        r"(^|[.!?;,]\s*)(?:please |pls |now )?you (?:just |then )?(?=\w)",
        lambda m: m.group(1) if starts_with_verb(text[m.end() :]) else m.group(0),
        text,
    )


def _said_after(text: str) -> str:
    """A sentence after the request that only says again which thing it meant: "pick up the block. not the blue
    one, the red one." is the red block; "put the bottle in the bowl. the bowl, not the rack." and "... yes, the
    wine rack, i know it's odd." say again a thing the request named, and add nothing to it."""
    m = re.fullmatch(r"(.+?[a-z'])\s*[.!?]+\s+(?:(?:yes|yeah|yep|right|correct),?\s+)?(.+?)\s*[.!?]*", text)
    if not m:
        return text
    request, after = m.group(1), m.group(2)
    one = r"(?:ones?|[a-z]+)"
    c = re.fullmatch(rf"not the ([a-z]+) ({one})\s*(?:,|;|-+)\s*(?:but |rather |i mean )?the ([a-z]+) ({one})", after)
    c = c or re.fullmatch(rf"()()the ([a-z]+) ({one})\s*(?:,|;|-+)\s*not the [a-z]+(?: {one})?", after)
    if c:
        said, noun = c.group(3), c.group(4)
        named = [
            n
            for n in re.finditer(r"\bthe ((?:[a-z]+ )?)([a-z]+)\b", request)
            if n.group(2) == noun or noun in ("one", "ones") and is_thing(n.group(2))
        ]
        if not named or len({n.group(2) for n in named}) > 1 or said in ("other", "same"):
            return text
        n = named[-1]
        return f"{request[: n.start()]}the {said} {n.group(2)}{request[n.end() :]}"
    # "milk in the basket. not the oj": a thing of another kind ruled out after the request adds nothing to it (it
    # must be in the scene all the same)
    other = re.fullmatch(r"(?:and |but )?not (?:the|a|an) ([a-z' ]+?)(?: (?:though|please|pls|ok|okay))?", after)
    noun = other.group(1).split()[-1] if other else ""
    if other and noun not in ("one", "ones", "other") and is_thing(noun) and not re.search(rf"\b{noun}\b", request):
        return f"there is the {other.group(1)}. {request}."
    # "not the bbq sauce, ketchup": the thing the request named, said again after the one ruled out
    again = re.fullmatch(
        r"not (?:the|a|an) [a-z' ]+?\s*(?:,|;|-+)\s*(?:but |rather |i mean )?(?:the |a |an )?([a-z' ]+)", after
    )
    if again and re.search(rf"\b{re.escape(again.group(1))}\b", request):
        return f"{request}."
    # "the bowl, not the wine rack" / "the wine rack, i know it's weird": a thing the request named, said again
    again = re.fullmatch(
        r"(the [a-z' ]+?)(?:\s*[,;-]+\s*(?:not (?:the|a|an) [a-z' ]+|(?:i|we|it|that|this)\b.*))?", after
    )
    if again and re.search(rf"\b{re.escape(again.group(1))}\b", request):
        return f"{request}."
    return text


def _conditioned_on_state(text: str) -> str:
    """ "if it is open, close it", "if the drawer's still shut, open it": a request made on the state it changes is
    the request (the skill checks its own post-condition); "it" is the thing whose state was said."""

    def request(m: re.Match) -> str:
        thing, rest = m.group(2), m.group(3)
        if thing != "it":
            rest = re.sub(r"\b(?:it)\b", thing, rest, count=1)
        return m.group(1) + rest

    return re.sub(
        r"(^|[.!?;]\s+)if (it|the [a-z' ]+?) (?:is|are|'s|was) (?:still |already |currently |now )?"
        r"(?:open|opened|closed|shut|on|off|lit|running)\s*,\s*(?:then\s+)?(?:please\s+)?"
        r"((?:close|shut|open|turn|switch|slide|push|pull)\b[^.!?;]*)",
        request,
        text,
    )


def _cut_off(text: str) -> str:
    """ "open the top dr- sorry, the bottom drawer": a phrase broken off mid-word and taken back; the phrase said
    after the correction stands in its place."""
    return re.sub(
        rf"\b(?:the|a|an) (?:[a-z]+ )*?[a-z]+-+\s*[,.]?\s*(?:{_CORRECTION}\b[\s,.]*)+(?=(?:the|a|an) )", "", text
    )


def _pointed_out_first(text: str) -> str:
    """ "see the ramekin? the black bowl beside it goes on the plate": a thing pointed out in a sentence of its own,
    then "it" where another thing is said to be: "it" is the thing pointed out."""
    m = re.match(
        r"(?:(?:do )?(?:you )?(?:see|notice|spot|spy)|look at|there(?:'s| is)) (the [a-z' ]+?)\s*[?.!:,]+\s+(?=\S)",
        text,
    )
    if not m:
        return text
    rest = re.sub(
        r"\b(beside|next to|near|by|behind|in front of|on top of|on|under|left of|right of|close to) it\b",
        rf"\1 {m.group(1)}",
        text[m.end() :],
        count=1,
    )
    return text if rest == text[m.end() :] else rest


def _verb_corrected(text: str) -> str:
    """ "close the drawer, no wait, i mean open it", "put the cube in the bowl, sorry, put it on the plate": a request
    said again with another verb after words that take it back replaces the request; "it" there is the thing the
    request acted on."""
    for m in _TAKEN_BACK_RUN.finditer(text):
        after = text[m.end() :]
        start = max(text.rfind(p, 0, m.start()) for p in ".!?;") + 1
        before = text[start : m.start()].strip()
        if not (before and starts_with_verb(before) and starts_with_verb(after)):
            continue
        verb, _, rest = after.partition(" ")
        said = _ACTED_ON.search(before)
        if said and re.match(r"(?:up |down )?(?:it|them)\b", rest):
            rest = re.sub(r"\b(?:it|them)\b", said.group(1), rest, count=1)
        return text[:start] + (" " if start else "") + f"{verb} {rest}".strip()
    return text


def _joined(text: str) -> str:
    """A superlative of place said with a hyphen as one word: "right-most" is "rightmost"."""
    return re.sub(r"\b(left|right|front|back|top|bottom|upper|lower|rear|fore)[- ]most\b", r"\1most", text)


def restructured(instruction: str) -> str:
    """The instruction said plainly and in the order its steps happen (see the module's docstring); the instruction
    itself when none of these applies."""
    text = re.sub(r"[ \t]+", " ", instruction.strip().lower().replace("\u2019", "'"))
    # a spec of keyed fields, said as a sentence; an end state said as a specification, said plainly; breaks said
    # aloud, written in (rules/transcript.py)
    # ... and colloquial phrases said plainly ("give it a proper scrub": rules/colloquial.py)
    out = spoken(end_state_framed(re.sub(r"\s+", " ", spelled_out(unpunctuated(plain_colloquial(text))))))
    text = re.sub(r"\s+", " ", text)
    # "once it's out far enough for your hand, grab ...": the state the step before made, said as a condition
    # (only after a sentence that opens it: "once the drawer is open, put ..." alone still asks to open it)
    out = re.sub(
        r"(?<=[.;!])(\s+)once (?:it|the drawer|that)(?:'s| is| has come| comes| has been pulled) (?:out|open|opened)"
        r"(?: (?:far )?enough)?(?: for (?:your|the) (?:hand|gripper|arm))?\s*,\s*",
        lambda m: m.group(1) if re.search(r"\bopen|\bpull", out[: m.start()]) else m.group(0),
        out,
    )
    # "the bowl next to the box (the right one)": a parenthesis saying which one, after a thing said by where it is,
    # is said of that thing, before its noun
    out = re.sub(
        r"\bthe ([a-z]+) ((?:next to|beside|near|by|on|in|at|behind|in front of) the [a-z ]+?)\s*"
        r"\(\s*the ([a-z]+) one\s*\)",
        r"the \3 \1 \2",
        out,
    )
    # a parenthesis that names the thing is an apposition between commas ("the smaller cube (the red one) on ...")
    out = re.sub(
        r"\s*\(\s*(the [a-z]+ ones?)\s*\)\s*(?=(\w)?)",
        lambda m: f", {m.group(1)}," + (" " if m.group(2) else ""),
        out,
    )
    # "the cream cheese (the little box, not the plate)": what sort of thing it is said again, and a thing ruled out
    out = re.sub(
        r"\s*\(\s*(?:the|a|an) (?:[a-z]+ )*?([a-z]+)\s*,\s*(not [a-z ]+?)\s*\)\s*(?=(\w)?)",
        lambda m: (
            (f", {m.group(2)}," + (" " if m.group(3) else "")) if m.group(1) in (*_GENERAL_NOUNS, "one") else m.group(0)
        ),
        out,
    )
    # a parenthesis that says where it is from the robot ("the first bowl (closest to you)"): "the one ..." between
    # commas; an item number ("bowl #1") says nothing perception could see
    out = re.sub(
        r"\s*\(\s*((?:closest|nearest|furthest|farthest|closer|nearer|further|farther)\b[a-z ]*"
        r"|(?:(?:located|sitting|placed|standing|positioned|lying) )?(?:on|to|at) (?:the|your) "
        r"(?:left|right|front|back)[a-z ]*)\s*\)\s*(?=(\w)?)",
        lambda m: (
            f", the one {re.sub(r'^(?:located|sitting|placed|standing|positioned|lying) ', '', m.group(1))},"
            + (" " if m.group(2) else "")
        ),
        out,
    )
    # ... but a number counted from a side is an ordinal ("drawer #3 from the top": the third drawer from the top)
    out = re.sub(
        r"\b([a-z]+)\s+(?:#\s?|no\. ?)([1-5])\s+(?=(?:counting )?from (?:the )?(?:top|bottom|left|right|front|back)\b)",
        lambda m: f"{_ORDINAL_WORDS[int(m.group(2)) - 1]} {m.group(1)} ",
        out,
    )
    out = re.sub(r"(?<=[a-z])\s+(?:#\s?|no\. ?)\d+\b", "", out)
    # a parenthesis that rules a thing out is a contrast between commas ("the top drawer (not the middle one)")
    out = re.sub(
        r"\s*\(\s*(not [a-z ]+?)\s*\)\s*(?=(\w)?)", lambda m: f", {m.group(1)}," + (" " if m.group(2) else ""), out
    )
    # a pause said with dots ("bbq sauce... pick it up and ..."): a sentence's end before a request said with a verb,
    # else only a pause ("put it... in the basket")
    out = re.sub(
        r"\s*(?:\.{2,}|\u2026)\s*(?=(\S[^.!?;]*)?)",
        lambda m: ". " if m.group(1) and starts_with_verb(m.group(1)) else " " if m.group(1) else "",
        out,
    ).strip()
    # "pull the drawer out > grab the cheese > place it in the drawer": steps listed with ">" between them; between
    # a thing and a place it is an arrow ("red block > green tray")
    out = re.sub(
        r"\s+(?:>|\u00bb)\s+(?=(\S[^>\u00bb]*))", lambda m: ", then " if starts_with_verb(m.group(1)) else " -> ", out
    )
    # "basket gets a can: not the tomato sauce, the alphabet soup", "the tray gets a cup: the red one": a place given
    # one of a kind, then which one
    out = re.sub(
        r"^((?:the )?[a-z ]+?) (?:gets|receives|needs|wants|takes) (?:a|an|one) ([a-z]+)\s*:\s*"
        r"(.*\b(?:the|a|an) [a-z].*?)\s*([.!]*)$",
        lambda m: re.sub(r"\bone\b", m.group(2), m.group(3)) + f" -> {m.group(1)}{m.group(4)}",
        out,
    )
    # "want red on top, green underneath": a wish said without its "i"
    out = re.sub(r"^(?:want|wanna|wanting)\s+(?!to\b)", "i want ", out)
    # "the one off to the left": on that side
    out = re.sub(r"(?<=\bone )(?:off|over|out) to the (left|right)\b(?! of\b)", r"on the \1", out)
    # "the cabinet has a drawer. open it ...": one of its parts, pointed out
    out = re.sub(
        r"(^|[.;!?] )the ([a-z ]+?) has (?:a|an|one) ((?:[a-z]+ )?(?:drawer|handle|knob|dial|door|lid|switch))"
        r"(?=\s*[.;,!])",
        r"\1there's a \3 on the \2",
        out,
    )
    # "top drawer open + cream cheese inside it": goals listed with "+"
    out = re.sub(r"\s+\+\s+(?=[a-z])", ", ", out)
    # "would you mind sorting these? red block into ...": what "these" are, said next
    # (also "sort these for me? ...", "sort these out - red block to ...")
    out = re.sub(r"\b(these|those|the following)(?: for me| for us| out| please)*\s*(?:\?|\s-+)\s+(?=\S)", r"\1: ", out)
    # ("would you mind sorting the blocks? red one into ...": the kind sorted, then each one's place)
    out = re.sub(
        r"\b(sort(?:ing)?|arrang(?:e|ing)|organi[sz](?:e|ing)) (?:the|these|those|both) \w+"
        r"(?: for me| for us| out| please)*\s*(?:\?|\s-+)\s+(?=\S)",
        lambda m: f"{m.group(1)} these: ",
        out,
    )
    # "the bowl resting on the stove, plate please", "not the bowl on the box, the other one. plate.": a thing said
    # without a verb, then only the name of where it goes (after a comma with "please", or as a sentence of its own)
    out = re.sub(
        r"^((?:not )?(?:(?:the|a|an) )?[a-z][a-z' ,]+?)(?:,(?=\s+(?:(?:on|onto|in|into) )?(?:the )?[a-z]+"
        r"(?: [a-z]+)?,? (?:please|pls|thanks|ta)\b)|\.(?=\s+(?:the )?[a-z]+\s*[.!]?$)"
        # (after a colon only a bare name: "blue tray: the red block, please" is the place said first)
        r"|:(?=\s+[a-z]+(?: [a-z]+)?,? (?:please|pls|thanks|ta)\b))\s+"
        r"(?:(on|onto|in|into) )?(?:the )?([a-z]+(?: (?!please|pls|thanks|ta)[a-z]+)?)"
        r"(?:,? (?:please|pls|thanks|ta))?\s*[.!]?$",
        # (a place word said keeps its relation: "..., on the plate please")
        lambda m: (
            f"{m.group(1)} {_INTO.get(m.group(2) or '', '->')} {'the ' if m.group(2) else ''}{m.group(3)}"
            if is_thing(m.group(3).split()[-1]) and not starts_with_verb(m.group(1))
            else m.group(0)
        ),
        out,
    )
    # "the bowl resting on the ramekin - plate, please": a thing, then where it goes
    out = re.sub(
        r"^((?:the|a|an) [a-z' ]+?)\s+-+\s+(?:the |onto the |into the |on the |in the )?([a-z]+(?: [a-z]+)?)"
        r"(?:,? please)?\s*[.!]?$",
        lambda m: f"{m.group(1)} -> {m.group(2)}" if is_thing(m.group(2).split()[-1]) else m.group(0),
        out,
    )
    # what is said in passing, appositions, a thing said first, and corrections, in this order
    for said in (
        _article_restored,
        _located_first,
        _pointed_then_described,
        _state_now,
        _being_apposition,
        _located_between_commas,
        _ordinal_restated,
        _thing_header,
        _said_in_passing,
        _wished,
        _ordinal_side_carried,
        _said_as_a_state,
        _pointed_and_urged,
        _manner_dropped,
        _dashed_apposition,
        _one_by_the_destination,
        _class_apposition,
        _bare_topic,
        _pointed_out_first,
        _you_before_verb,
        _asked_if_done,
        _destination_said_last,
        _kindless_one,
        _located_topic_contrasted,
        _topic_carried,
        _said_after,
        _conditioned_on_state,
        _cut_off,
        _verb_corrected,
        _self_corrected,
    ):
        out = said(out)
    out = _its_part(_negated_state(_joined(_but_clause(_restated_one(_row_restated(_named_in_apposition(out)))))))
    for step in (
        _header,
        _present_goal,
        _former_latter,
        _cleft,
        _temporal,
        _context,
        _unwanted_now,
        _counted_kind,
        _one_of_count,
        _chosen,
        _state_after,
        _other_after_contrast,
        _of_all_the_things,
        _not_there_but,
        _restack,
        _first_said_last,
        _on_top_of_last,
        _said_again,
        _apposed_contrast,
        _contrast,
        sequenced,
    ):
        out = step(out)
    return instruction if out == text else out
