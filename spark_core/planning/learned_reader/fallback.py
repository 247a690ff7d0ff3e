"""The learned reading of an instruction every rule reading refused: the goal the scorer ranks first among those
the scene view affords, when it is confident.

It is tried only when the rules refused for want of a reading (`may_read`), not because a thing is absent or
ambiguous or a check of the plan failed: every phrase perception found nothing for is a misreading that names no
thing of its own, and every kind it found several of is named precisely by another phrase. Its goals only use
found phrases and pass the planner's own checks (kinds, near-miss names, nothing put on itself), so it never plans
around a thing the scene does not hold; a sentence that asks for nothing, or a goal that leaves a found phrase
out, is never planned."""

from __future__ import annotations

import math
import re

from lemminflect import getAllLemmas

from ...perception.colors import BASE_COLOURS
from ...perception.colors import SYNONYMS as COLOUR_SYNONYMS
from ...perception.lexicon.nouns import nouns
from ..protocol import PlanRequest
from ..rules.framing import verb_words
from ..rules.lexicon import PARTICIPLES, STATE_ACTIONS, VERBS
from ..rules.mentions import PLACE_WORDS
from ..rules.parse import Clause
from ..rules.planner import RulesPlanner, composer
from ..rules.things import NOUNS_IT_MISSES, is_verb
from .candidates import options
from .scorer import NONE_SCORE, load

# The top goal's probability (softmax over the instruction's goals and "none of these") below which the reader
# declines. On the held-out tenth of the dev examples (train.py): 178 right and 3 wrong of 186 goals kept at 0.5,
# none wrong at 0.7 but 50 fewer right.
THRESHOLD = 0.5
# Refusals that stand whatever the reader makes of the sentence: the robot lacks an arm, a thing is absent by its
# kind. Said anywhere in the message (a clause's text may come first): a word of the instruction itself matching
# one only makes the reader stand back, the safe way.
_STANDS = ("could not single", "arms are", "needs two arms", "needs a second handle", "nothing there is")
_WHICH = re.compile(r"""which (?:'([^']*)'|"([^"]*)")""")
# Words that name no thing: a phrase of only these, verbs and words of what perception found is a misreading of
# the sentence ("blue not block", "there once it", "cabinet drawer is"), not a thing the scene lacks.
_NAMES_NOTHING = frozenset(
    ["a", "an", "the", "this", "that", "these", "those", "it", "its", "them", "they", "there", "here", "one", "ones"]
    + ["not", "no", "never", "do", "does", "did", "is", "are", "was", "be", "been", "has", "have", "had", "got"]
    + ["dont", "don't", "doesnt", "isnt", "wont", "cant"]
    + ["once", "then", "now", "just", "so", "and", "or", "but", "if", "when", "while", "until", "as", "than"]
    + ["in", "on", "at", "of", "to", "into", "onto", "from", "with", "by", "for", "up", "down", "out", "off", "over"]
    + ["against", "back", "other", "same", "also", "too", "very", "i", "you", "me", "we", "us", "my", "your"]
    # closed-class words the lexicon has no lemma for (so they would count as unknown, maybe a thing): relative and
    # question words, prepositions, conjunctions, quantifiers, greetings; none names a thing on a table
    + ["which", "whose", "whom", "what", "who", "whatever", "whichever", "where", "whether", "whereas", "because"]
    + ["although", "unless", "whilst", "till", "beside", "behind", "underneath", "beneath", "above", "among"]
    + ["amongst", "toward", "towards", "upon", "via", "per", "despite", "during", "atop", "amid", "neither", "nor"]
    + ["both", "each", "every", "all", "any", "some", "none", "another", "such", "okay", "ok", "yes", "yeah"]
    + ["nope", "hey", "hi", "hello"]
    # chat shorthand: words of the register, none a thing
    + ["lol", "lmao", "omg", "pls", "plz", "thx", "ty", "btw", "tbh", "imo", "asap", "rn", "fwd", "ur", "u", "ya"]
    # verbs of a stated goal whose noun senses are no thing on a table ("the red cube goes ...")
    + ["goes", "must", "want", "wants", "need", "needs", "sitting", "resting"]
)
_NOT_FOUND = re.compile(r"""could not find (?:'([^']*)'|"([^"]*)")""")


def _may_be_thing(word: str) -> bool:
    """A word that may name a thing: a noun, or a word the lexicon does not know (taken as one, the safe way), unless
    WordNet files every sense of it as no thing on a table (a person, a group, an act: "grandma", "folks")."""
    if word in NOUNS_IT_MISSES:
        return True
    lemmas = getAllLemmas(word)
    if lemmas and "NOUN" not in lemmas and "PROPN" not in lemmas:
        return False
    return not nouns().names_no_thing(word)


# Words after which a word that may be a noun or a verb is the verb ("do not touch", "it sits", "to box").
_VERB_BEFORE = frozenset(
    ["not", "never", "dont", "don't", "doesnt", "doesn't", "do", "does", "did", "to", "it", "they", "i", "you", "we"]
    + ["will", "would", "can", "could", "should", "must", "shall", "may", "might"]
    + ["one"]  # "(but that) one goes in the tray": a thing said as "one" does what follows
)


def misread(phrase: str, known: set[str]) -> bool:
    """A phrase perception found nothing for that names no thing of its own: every word is a word of what
    perception found, a word that names nothing, no noun, or a word that may be a verb said right after a word
    that only a verb follows ("do not touch red block", "dont touch"). A phrase with a
    noun perception found nothing for ("banana", "red ball", "pot handle", "the box") is not misread: that thing
    is absent. Words that only place a thing ("table", "front", "you", `mentions.PLACE_WORDS`) and the participles
    that say where it lies ("sitting", "lying") name nothing to look for either: "table in front of you grey stove
    sitting" is a misreading of a found "grey stove"."""
    words = phrase.split()
    # a phrase ending in a word of description, not a thing ("look nicer"): its words before may be verbs
    described = words[-1] not in _NAMES_NOTHING and not _may_be_thing(words[-1])

    def placed(i: int) -> bool:
        w = words[i]
        if w in known or w in _NAMES_NOTHING or w in PLACE_WORDS or w in PARTICIPLES or not _may_be_thing(w):
            return True
        return is_verb(w) and (described or (bool(i) and words[i - 1] in _VERB_BEFORE))

    # "toss the yellow block in there" among a green block: a colour no found phrase has, said of a thing, is
    # another thing of that kind, absent
    colours = [w for w in words if (w in BASE_COLOURS or w in COLOUR_SYNONYMS) and w not in known]
    if colours and any(_may_be_thing(w) and w not in BASE_COLOURS and w not in COLOUR_SYNONYMS for w in words):
        return False
    return all(placed(i) for i in range(len(words)))


_RELATIONS = frozenset(["on", "in", "at", "of", "next", "to", "near", "by", "beside", "between", "under", "behind"])


def _named_precisely(phrase: str, found: list[str]) -> bool:
    """Another phrase of the sentence perception found once names the same kind with every word of `phrase` before
    any relation ("the top drawer ... that drawer", "the black bowl on the cookie box ... the black bowl"): the
    sentence says which one it is. "square nut next to round peg" names a nut, not which "peg"."""
    words = phrase.split()
    for p in found:
        said = p.split()
        thing = said[: next((i for i, w in enumerate(said) if w in _RELATIONS), len(said))]
        if p != phrase and thing and thing[-1] == words[-1] and set(words) <= set(thing):
            return True
    return False


def may_read(error: str | None, request: PlanRequest) -> bool:
    """The rules' refusal is one the reader may read past: a failure to read the sentence ("did not understand",
    a phrase perception found nothing for, a "which" of a kind it found several of), never a check of the plan
    (no handle, no tool, a substance it cannot show). Every phrase perception found nothing for is a misreading
    (`misread`), none a thing the scene lacks; every phrase it found several of, and the one the refusal asks
    "which" of, is named precisely by another phrase it found once."""
    if not error or any(s in error for s in _STANDS):
        return False
    which, said = _WHICH.match(error), _NOT_FOUND.match(error)
    if not (error.startswith("did not understand") or which or said):
        return False
    scene = request.scene
    found = list(scene.keypoints)
    # words of what perception found for the sentence, not of all the scene holds: the reader ranks goals over the
    # found phrases only, so a thing said in a misreading ("plate but") that was not found would be planned around
    known = {w for p in found for w in re.findall(r"[a-z]+", p.lower())}
    for phrase, why in scene.unresolved.items():
        if not (_named_precisely(phrase, found) if why.startswith("several") else misread(phrase, known)):
            return False
    if which is not None and not _named_precisely(which.group(1) or which.group(2), found):
        return False
    return said is None or (said.group(1) or said.group(2)) in scene.unresolved


# Words that say a goal without a verb of the lexicon: where a thing goes, a wish, a duty.
_GOAL_WORDS = frozenset(
    ["in", "into", "on", "onto", "inside", "atop", "over", "up", "off", "out", "away", "back", "open", "shut"]
    + ["should", "must", "want", "wants", "need", "needs", "belongs", "belong", "goes", "go", "let", "get", "have"]
    + ["make", "give", "hold", "hand", "bring", "take", "fetch", "carry", "stow", "keep", "leave", "clean"]
)


def says_a_goal(instruction: str) -> bool:
    """The sentence has a word that can say what is to be done: a verb the lexicon knows in any form, a
    goal-state word, a place a thing goes to, a wish or a duty. "the pear is ripe and the bin is green" has none:
    a description, not a request, whatever goal its things afford."""
    words = re.findall(r"[a-z']+", instruction.lower())
    verbs = verb_words()
    states = {w for s, _ in STATE_ACTIONS for w in s.split()} | set(PARTICIPLES)
    for w in words:
        if w in _GOAL_WORDS or w in verbs or w in states:
            return True
        if any(lemma in verbs for lemma in getAllLemmas(w).get("VERB", ())):
            return True
    return False


# Words before a thing that say it is to be left alone or is not the one meant ("dont touch the red block", "not
# the bowl on the cabinet", "ignore the mug"); said before these, a negation asks for something after all.
_LEFT_ALONE = frozenset(["not", "never", "dont", "don't", "ignore", "ignoring", "without", "except", "besides"])
_STILL_ASKS = frozenset(["forget", "fail", "hesitate", "stop", "just", "only"])
_PARTS = ("handle", "knob")


def left_alone(phrase: str, instruction: str) -> bool:
    """The phrase is said, word for word, within four words after a word that leaves it alone or sets it apart
    ("turn the stove on. dont touch the red block"): no goal has to use it."""
    tokens = re.findall(r"[a-z']+", instruction.lower())
    words = phrase.split()
    for i in range(len(tokens) - len(words) + 1):
        if tokens[i : i + len(words)] != words:
            continue
        before = tokens[max(0, i - 4) : i]
        if set(before) & _LEFT_ALONE and not set(before) & _STILL_ASKS:
            return True
    return False


# A phrase that counts several things ("two cubes", "both blocks"): no one keypoint stands for it.
_COUNTED = re.compile(r"(?:the )?(?:two|three|four|five|both|all|several|many|some|each|every)\b")

# Kinds of carrying, one kind of doing to `said_actions`: "pick up X and drop it in Y" is a put.
_CARRY = frozenset(["pick", "put", "stack", "sort"])


# Verbs that say a thing goes somewhere: a goal of theirs is more than a pick.
_PLACED = frozenset(["put", "stack", "sort"])


def _kinds(actions: set[str]) -> set[str]:
    return {"carry" if a in _CARRY else a for a in actions}


def said_actions(instruction: str) -> set[str]:
    """The actions the sentence's own verbs name without doubt: a two-word verb of the lexicon ("turn on", "pick
    up"), or a one-word verb in any form that is nothing but a verb ("pour", "poured"; not "close", "empty",
    "stack", which also describe or name)."""
    words = re.findall(r"[a-z]+", instruction.lower())
    lemmas = [getAllLemmas(w) for w in words]
    out: set[str] = set()
    for action, forms in VERBS.items():
        for said in (form.split() for form in forms):
            for i, w in enumerate(words):
                if w != said[0] and said[0] not in lemmas[i].get("VERB", ()):
                    continue
                two_words = len(said) > 1 and words[i + 1 : i + len(said)] == said[1:]
                if two_words or (len(said) == 1 and set(lemmas[i]) <= {"VERB"}):
                    out.add(action)
    return out


def _unused(clauses: tuple[Clause, ...], found: list[str], instruction: str) -> list[str]:
    """Phrases perception found that the goal leaves out: neither one of its things, nor a word of one (what
    locates it: "plate" of "black bowl next to plate"), nor one with a part of it ("stove knob" of "stove"), nor a
    part the planner looked for though the sentence does not say it ("drawer handle"), nor a thing the sentence
    leaves alone (`left_alone`)."""
    used = [p for c in clauses for p in (c.obj, c.target, c.source, c.tool) if p]
    words = {w for p in used for w in p.split()}
    said = set(re.findall(r"[a-z]+", instruction.lower()))
    return [
        p
        for p in found
        if p not in used
        and p.split()[-1] not in words
        and not any(u in p for u in used)
        and not (p.split()[-1] in _PARTS and p.split()[-1] not in said)
        and not left_alone(p, instruction)
    ]


_INTO = r"(?:into|onto|inside|in|on|on top of|atop)"


def _swapped(clauses: tuple[Clause, ...], instruction: str) -> tuple[str, str] | None:
    """(object, destination) of a carry the sentence says the other way round: its destination's noun said before a
    place word that its object's noun follows ("squeeze the whole basket into the green block" for "put the green
    block in the basket"); None when no carry is said so."""
    text = " ".join(re.findall(r"[a-z]+", instruction.lower()))
    for c in clauses:
        if c.action not in _CARRY or not c.obj or not c.target:
            continue
        obj, dst = c.obj.split()[-1], c.target.split()[-1]
        if obj == dst or re.search(rf"\b{obj}\b.*\b{_INTO}\b.*\b{dst}\b", text):
            continue
        if re.search(rf"\b{dst}\b(?: \w+){{0,3}} {_INTO} (?:the |a |an )?(?:\w+ )?{obj}\b", text):
            return c.obj, c.target
    return None


def read(request: PlanRequest, planner: RulesPlanner) -> tuple[list[dict], list[str]] | str | None:
    """(steps, what was understood) for the confident top goal; else why the reader declined; None when no reader
    weights are installed."""
    model = load()
    if model is None:
        return None
    if not says_a_goal(request.instruction):
        return "the sentence says no goal: no word in it asks for one"
    compose, effect = composer(planner, request)
    goals = options(list(request.scene.keypoints), compose, effect)
    if not goals:
        return "the things found afford no goal the planner can compose"
    scores = model.scores(request.instruction, [c.text for c, _ in goals])
    top = max(scores)
    total = sum(math.exp(s - top) for s in [*scores, NONE_SCORE])
    k = scores.index(top)
    p = 1.0 / total
    text = goals[k][0].text
    if p < THRESHOLD:
        return f"its best guess, {text!r}, had probability {p:.2f} (below {THRESHOLD})"
    verbs, done = said_actions(request.instruction), {c.action for c in goals[k][0].clauses}
    if verbs and not _kinds(verbs) & _kinds(done):  # "pour the pot into its own handle"
        return f"its best guess, {text!r}, does not do what the sentence's verbs say ({', '.join(sorted(verbs))})"
    if verbs & _PLACED and not done - {"pick"}:  # "pick up the cube and put it on the other one": not a pick alone
        return f"its best guess, {text!r}, puts nothing anywhere, and the sentence says to put something"
    counted = [p for c in goals[k][0].clauses for p in (c.obj, c.target, c.source) if p and _COUNTED.match(p)]
    if counted:  # "swap the two cubes around ...": a step on one thing cannot act on a count of them
        return f"its best guess, {text!r}, acts on {counted[0]!r} as if it were one thing"
    swapped = _swapped(goals[k][0].clauses, request.instruction)
    if swapped:  # "squeeze the whole basket into the green block": the sentence says the other way round
        return f"its best guess, {text!r}, puts {swapped[0]!r} into what the sentence puts into {swapped[1]!r}"
    left = _unused(goals[k][0].clauses, list(request.scene.keypoints), request.instruction)
    if left:  # a part of the request no step would carry out: never a partial plan
        return f"its best guess, {text!r}, leaves out {', '.join(map(repr, left))}"
    return goals[k][1], [f"read by the learned reader as {text!r} (probability {p:.2f} among {len(goals)} goals)"]
