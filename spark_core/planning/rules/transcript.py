"""Speech as a speech-to-text system writes it: lower case and hardly a full stop ("see the red block yeah pick that
up and drop it into the bowl", "open up the drawer on the cabinet grab the red block and then put it into the
drawer", "the bowl on top of the ramek- no on top of the cookies i'd like it on the plate"). The sentence breaks a
speaker says with a discourse word or with the next request's verb are written back in, and a word broken off and
taken back is replaced by what follows it. discourse.restructured's first step."""

from __future__ import annotations

import re

from ...perception.colors import BASE_COLOURS
from ...perception.lexicon.nouns import nouns
from .lexicon import DETERMINERS
from .things import is_thing

# Requests said with these verbs: a new request, when one starts right after a thing is named.
_REQUEST_VERBS = (
    r"grab|take|pick|put|place|set|drop|stick|lift|raise|open|close|shut|push|pull|slide|nudge|move|turn|switch|"
    r"stack|pour|tip|scrub|wipe|bring|carry|get|lower|pop|toss|lay|leave"
)
# What a request's verb is said before: the thing it acts on (an article, a pronoun, a possessive).
_ACTED_ON = r"(?:the|a|an|it|that|this|them|those|these|my|your|its|both|one)\b"
# A wish said of the thing just named ("the bowl on the cookies i'd like it on the plate").
_WISH = r"(?:i|we)(?:'d| would)? (?:like|want|need) (?:it|that|them|this)\b"
# Words a speaker starts the next sentence with, aloud.
_MARKERS = r"(?:yeah|yep|yes|okay|ok|alright|now|um+|uh+|erm|er)"
# A word broken off ("ramek-") and taken back ("no", "wait", "sorry", "i mean").
_BROKEN_OFF = re.compile(r"\b([a-z]+)-\s+(?:no,? wait|wait,? no|no|wait|sorry|i mean|er|uh|um)\b[,.]?\s+")
# Words that end no thing's name, whatever the lexicon says ("it", "up" and "you" are nouns to it).
_NO_NAME = frozenset(
    [*DETERMINERS, "it", "them", "me", "you", "us", "him", "her", "we", "i", "they", "up", "out", "down", "in", "on"]
    + ["off", "over", "back", "away", "now", "then", "there", "here", "too", "also", "please", "and", "or", "but"]
    + ["so", "just", "again", "to", "can", "could", "would", "will", "should", "must", "let", "lets", "help", "try"]
    # words of order and of speech ("okay first pull ...", "and then uh take ...")
    + ["first", "next", "last", "finally", "afterwards", "okay", "ok", "yeah", "yep", "yes", "alright", "well"]
    + ["um", "umm", "uh", "uhh", "er", "erm", "hmm", "like", "actually", "maybe", "basically"]
    # relatives and the verbs a clause is built with ("after which set it ...", "shall be put ...")
    + ["which", "who", "whom", "what", "whichever", "whatever", "be", "been", "being", "is", "are", "was", "were"]
    + ["am", "get", "got", "have", "has", "had", "do", "does", "did", "shall", "may", "might", "gonna", "wanna"]
)
# Where a level of a stack is said: the next level follows without a comma ("blue on the bottom green in the middle").
_LEVEL = r"(?:on|at) the (?:bottom|top|base)|in the middle|on top|at the top|underneath|below"


def unpunctuated(text: str) -> str:
    """`text` (lower-cased) with the breaks a speaker said written in and words taken back replaced (see the module's
    docstring); `text` itself when it has none."""
    out = _repaired(text)
    # "the wine bottle yeah that one pick it up": the thing pointed at again, no word of the request
    out = re.sub(r"(?<=[a-z]) (?:yeah|yep|yes),? (?:that|this)(?: one)?(?= )", "", out)
    # "see the red block yeah pick that up": a discourse word and then a request's verb start a new sentence
    out = re.sub(
        rf"(?<![,.;:!?])(?<!\band)(?<!\bthen)(?<!\bto) (?:{_MARKERS} )+(?=(?:{_REQUEST_VERBS}) (?:(?:up|out|down|in) )?"
        rf"{_ACTED_ON})",
        ". ",
        out,
    )
    # "open up the drawer on the cabinet grab the red block": a request's verb (or a wish) right after a thing's
    # name starts one; after a thing said first ("the bowl that isn't on the cookies put that on the plate"), a
    # clause that acts on it
    out = re.sub(
        rf"(?<![\w'-])([a-z]+) (?=(?:(?:{_REQUEST_VERBS}) (?:(?:up|out|down|in) )?{_ACTED_ON}|{_WISH}))",
        lambda m: f"{m.group(1)}{_break(m)} " if _names_a_thing(m.group(1)) and not _fronted(m) else m.group(0),
        out,
    )
    # "a tower with blue on the bottom green in the middle and red on top": one level per clause
    colours = "|".join(BASE_COLOURS)
    return re.sub(rf"\b({_LEVEL}) (?=(?:{colours})\b)", r"\1, ", out)


def _break(m: re.Match) -> str:
    """A comma after a thing said first, with no verb before it in its sentence; else a full stop."""
    sentence = re.split(r"[.;!?]\s+", m.string[: m.start()])[-1]
    return "," if re.match(r"(?:the|a|an|this|that|those|these|my|your|our)\b", sentence) else "."


def _fronted(m: re.Match) -> bool:
    """The thing is said in a phrase put first ("from the two mugs take the one ..."): the request follows it."""
    sentence = re.split(r"[.;!?]\s+", m.string[: m.start()])[-1]
    return bool(re.match(r"(?:from|of|among|out of|between|in|on|inside|next to|by)\b", sentence))


def _names_a_thing(word: str) -> bool:
    """The word can end a thing's name: a noun, not a pronoun, particle or word a request is said with ("can you
    put ...", "turn the stove on and set ...")."""
    if word in _NO_NAME or re.fullmatch(_REQUEST_VERBS, word):
        return False
    return is_thing(word) or bool(nouns().senses(word))  # (the rules' lexicon lacks some: "tin")


def _repaired(text: str) -> str:
    """ "the bowl on top of the ramek- no on top of the cookies": what follows the broken-off word replaces what
    was said from where its first words were said before (the last such place), else the broken-off word alone."""
    m = _BROKEN_OFF.search(text)
    if m is None:
        return text
    before, after = text[: m.start()].rstrip(), text[m.end() :]
    words = after.split()
    for n in (3, 2, 1):
        at = f" {before} ".rfind(f" {' '.join(words[:n])} ") if len(words) >= n else -1
        if at >= 0:  # (an index into `before`: the padding's leading space stands for the match's own)
            return _repaired(f"{before[:at].rstrip()} {after}".strip())
    return _repaired(f"{before} {after}".strip())
