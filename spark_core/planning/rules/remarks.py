"""Remarks: whole sentences after the request that say nothing to do ("lift the red cube. just want to see the grasp
work", "put the block on the plate. don't just set it down next to it", "take the bowl on the stove. the other bowl
can stay where it is"), and trailing clauses that name nothing of the scene ("put the bowl on the stove, we're
going to warm something up in it", "..., tipping it slowly so none of them spill"). When every reading of the whole
instruction refuses, the planner reads it again without them (planner._without_remarks): the request must then plan
on its own, and a remark may name no kind of thing the scene lacks, so an absent thing is still refused."""

from __future__ import annotations

import re
from collections.abc import Callable

from lemminflect import getAllLemmas

from ...perception.colors import BASE_COLOURS
from ...perception.lexicon.nouns import nouns
from ...perception.variants import KIND_OF
from .lexicon import DETERMINERS, STATE_ACTIONS, VERBS
from .phrases import singular
from .rewrite import starts_with_verb
from .things import NOT_THINGS, names_a_thing

# An occasion or a run of the robot, not a thing ("so it can warm up before dinner", "for the next trial").
_OCCASIONS = frozenset(
    ["dinner", "lunch", "breakfast", "supper", "meal", "party", "guests", "test", "trial", "experiment", "demo"]
    + ["episode", "session", "shift", "day", "night", "morning", "evening", "week", "weekend", "tonight", "later"]
    + ["run", "attempt", "batch", "rollout"]
)
# The surface everything stands on ("so it's off the worktop"): no thing of the scene.
_SURFACES = frozenset(["table", "tabletop", "worktop", "countertop", "counter", "benchtop", "bench", "surface"])
# Words that name no thing of the scene, whatever the lexicon says.
_SELVES = frozenset(
    ["myself", "yourself", "itself", "ourselves", "themselves", "himself", "herself", "other", "others"]
    + ["nothing", "something", "anything", "everything", "stuff", "none", "each", "either", "neither", "lot", "lots"]
    + ["its", "his", "her", "their", "our", "your", "my", "mine"]
    # question words (the lexicon says noun)
    + ["which", "whichever", "what", "whatever", "how", "where", "who", "whether"]
    + ["thanks", "thank", "thx", "ty", "cheers", "please", "pls", "mate", "buddy"]  # a courtesy
    # the scene's things all together ("we're packing the groceries away"), never one thing perception looks for
    + ["groceries", "grocery", "items", "objects", "belongings", "scene", "setup", "workspace", "everyone"]
    # the robot itself and who watches it ("so everyone can see the gripper working", "fingers crossed")
    + ["robot", "gripper", "camera", "fingers", "finger", "audience", "viewers", "photo", "picture", "video"]
    + list(_SURFACES)
    + list(_OCCASIONS)
)

# What makes a sentence after the request a remark: a negation (how not to do it), the speaker's own say ("just want
# to see ...", "i do the rest myself"), or a thing left as it is ("the other bowl can stay where it is", "fyi").
_REMARK = re.compile(
    r"\b(?:not|never|don't|dont|doesn't|won't)\b|n't\b|^(?:i|we|my|our|just|fyi|btw|nothing else)\b|"
    r"^no \w+ing\b|"  # how not to do it ("no lifting, just push")
    r"^(?:there is )?no need\b|"  # what not to do ("just lift it; no need to put it anywhere")
    r"^(?:that is|that's|this is) (?:the|my) (?:order|sequence)\b|"  # the steps' order said again
    # the session, not the task: another day or another task ("same picture as yesterday", "the next scene is the
    # long one")
    r"\b(?:yesterday|last time|last week|the (?:next|last|previous|other) (?:scene|task|trial|run|episode|round))\b|"
    r"\bearlier (?:in the week|today|this week|on)\b|^in (?:that|this|the same) order\b|^only (?:that|this) one\b|"
    # the other things kept as they are ("the top and bottom stay shut")
    r"\b(?:stay|stays|remain|remains) (?:shut|closed|open|off|on|where they are|as they are)\b|"
    r"\b(?:can|should|may|will) (?:stay|remain|be left)\b|\b(?:stays?|remains?) (?:where|as|put)\b|\bfyi\b|\bbtw\b"
)
# A remark never says the request itself in other words ("i want the red cube on the green one").
_WISH = re.compile(r"\b(?:want|need|would like|'d like|wish|prefer) (?:the|it|them|a|an|this|that|those|these)\b")


def remarks(instruction: str) -> tuple[str, list[str]]:
    """The instruction without the remark sentences after its first imperative one (its first, when none is), and
    those remarks; the instruction itself and no remarks when it has none."""
    said = [s.strip() for s in re.split(r"(?<=[.!?;])\s+", instruction.strip()) if s.strip()]
    # (none said with a verb: the first says the goal, "red block -> bowl. short one, ...")
    main = next((i for i, s in enumerate(said) if starts_with_verb(_plain(s))), 0)
    if len(said) < 2:
        return instruction, []
    aside = [i for i, s in enumerate(said) if i > main and _REMARK.search(_plain(s)) and not _WISH.search(_plain(s))]
    if not aside:
        return instruction, []
    return " ".join(s for i, s in enumerate(said) if i not in aside), [said[i] for i in aside]


# Words after which a word that may be a verb is one ("none of them spill", "it squishes", "we warm it").
_SUBJECTS = frozenset(["i", "we", "you", "they", "them", "it", "he", "she", "to", "will", "would", "might", "could"])
# Where a trailing clause may start: a comma, a dash, a semicolon or a sentence's end, or a word that joins a reason
# or a result ("... so none of them spill", "... because it's soft").
_CLAUSE = re.compile(r"\s*(?:[,;:]|\s-+\s|(?<=[.!?])\s)\s*|\s+(?=(?:so|because|since|as|cause|cuz)\s)")
# Words a clause that only remarks never says: a colour, "one" (which thing), a word that orders steps.
_ASKS = frozenset([*BASE_COLOURS, "one", "ones", "then", "also", "first", "next", "after", "before", "once"])
# A verb of the planner's own says a step where it leads the clause or follows a word that leads one ("..., then
# open the drawer", "..., and to close it"); after its subject it says how things are ("it should sit flat").
_STEP_VERBS = frozenset(
    [f.split()[0] for forms in VERBS.values() for f in forms]
    + [s.split()[0] for s, _ in STATE_ACTIONS if s.split()[0] not in ("on", "off", "in", "out", "up", "down")]
)
_LEADS = frozenset(["", "and", "then", "also", "please", "to", "just", "now", "so", "pls"])
# Verbs after which a word says how a thing stands ("sit flat", "stay upright", "be level").
_POSTURES = frozenset(["sit", "sits", "stand", "stands", "stay", "stays", "be", "remain", "remains", "lie", "lies"])
# A purpose said as "for" and a noun with no article ("we need it for dinner"): no thing of any scene.
_PURPOSE = re.compile(
    r"\bfor (?:the )?(?:dinner|lunch|breakfast|later|now|tonight|today|tomorrow|safety|science)\b"
    # what the thing is wanted for ("we'll need it for pasta tonight", "it's for the soup"): the dish, not a thing here
    r"|\b(?:need|use|want|keep|save) (?:it|them|this|that) for (?:the |a |an |some |my |our )?\w+"
    # ... or said of it with a time ("it's for the pasta tonight"; "it's for the banana" may ask for a banana)
    # ... or made by the speaker ("for the cookies i bake"): what they make, not a thing here
    r"|\bfor (?:the |my |our |some )?\w+(?: \w+)? (?:i|we) "
    r"(?:bake|make|cook|prepare|am making|'m making|want to make)\b"
    r"|\b(?:it is|it's|they are|they're|that is|that's) for (?:the |a |an |some |my |our )?\w+"
    r"(?= (?:tonight|later|today|tomorrow|this (?:evening|morning|afternoon|weekend)))"
)
# The speaker's own doing said after the request ("i need to put something in it later", "we're going to ...").
_SPEAKER_DOES = re.compile(r"(?:i|we)(?: will| would| am| are| ll| re| m| d)? (?:need|want|have|going|plan|hope) to\b")
# The speaker's own cooking or occasion said after the request ("i'm making pasta later", "we're having guests"):
# what they make or have is no thing asked of the robot, so it may be absent from the scene.
_SPEAKER_BUSY = re.compile(
    r"(?:i|we)(?: am| are| m| re| ll| will(?: be)?) "
    r"(?:making|cooking|baking|prepping|preparing|having|hosting|serving)\b"
)
# How many trailing clauses, at most, are tried: each try is a reading of its own.
_MAX_TAILS = 4


def trailing_remarks(instruction: str, found: list[str]) -> list[tuple[str, str]]:
    """(the instruction up to a clause boundary, the clauses after it) for each boundary whose clauses after it are
    remarks: they name none of `found` (perception's phrases and inventory) and no thing the scene lacks, and say no
    step, colour or "one". Longest kept first; at most `_MAX_TAILS`."""
    # a phrase perception was asked for that starts with who does something ("we packing groceries away") names
    # no thing, whatever perception made of it
    named = [p for p in found if p.lower().split()[:1] not in (["we"], ["i"], ["they"], ["you"])]
    known = {w for p in named for w in re.findall(r"[a-z]+", p.lower())}
    known |= {singular(w) for w in known}
    text = instruction.strip()
    out: list[tuple[str, str]] = []
    cuts = [m for m in _CLAUSE.finditer(text) if m.start() > 0 and m.end() < len(text)]
    for m in reversed(cuts):
        kept, tail = text[: m.start()].strip(), text[m.end() :].strip()
        words = re.findall(r"[a-z]+", _plain(tail))
        if not words or not re.search(r"[a-z]", kept.lower()):
            continue
        pairs = list(zip(["", *words], words))
        # the speaker's own doing ("i need to put something in it later"): a verb after it is no step of the robot's
        speaker = _SPEAKER_DOES.match(" ".join(words))
        if not speaker and any(w in _STEP_VERBS and before in _LEADS for before, w in pairs):
            break  # a step of its own
        # how it stands ("it should sit flat on it"): a state, not a thing
        # ... and "the next <noun>", "before dinner" say an occasion ("for the next trial"), not the next step
        after = [*words[1:], ""]
        # ... nor the surface everything stands on ("off the worktop"), nor "on target" (where it should be)
        words = [
            w
            for (before, w), then in zip(pairs, after)
            if before not in _POSTURES
            and not _occasion(before, w, then)
            and w not in _SURFACES
            and (before, w) != ("on", "target")
        ]
        if any(w in _ASKS or w in known or singular(w) in known for w in words):
            break  # a longer tail holds this one: it names the scene or asks too
        busy = _SPEAKER_BUSY.match(" ".join(re.findall(r"[a-z]+", _plain(tail))))
        if not busy and names_absent(_PURPOSE.sub(" ", _plain(tail)), found):
            break
        out.append((kept, tail))
        if len(out) == _MAX_TAILS:
            break
    return out


def _occasion(before: str, word: str, after: str) -> bool:
    """An ordering word said of an occasion, not of a step: "the next trial", "before dinner"."""
    return (word == "next" and before in ("the", "a")) or (word in ("before", "after") and after in _OCCASIONS)


def names_absent(sentence: str, found: list[str]) -> str | None:
    """A word of `sentence` that names a kind of thing none of `found` (perception's phrases and inventory) is of,
    or a noun-only word none of them holds ("don't touch the banana" in a scene without one); None when it names
    no such thing."""
    known = {w for p in found for w in re.findall(r"[a-z]+", p.lower())}
    kinds = set().union(*(KIND_OF.get(w, frozenset()) | KIND_OF.get(singular(w), frozenset()) for w in known))
    words = re.findall(r"[a-z]+", _plain(sentence))
    for before, w in zip(["", *words], words):
        forms = {w, singular(w)}
        if forms & known or (before in _SUBJECTS and "VERB" in getAllLemmas(w)):
            continue  # said of the scene, or a verb after its subject ("so none of them spill")
        kind = next((KIND_OF[f] for f in forms if f in KIND_OF), None)
        if kind is not None and not forms & NOT_THINGS:  # a place word ("an odd spot") says where, not what
            if not kind & (known | kinds):
                return w
            continue
        # a word only ever a noun, that names a thing ("laptop"), not a pronoun ("myself") or a word of time or
        # manner ("bit", "way")
        # (a person or a group, "nobody", "the baby", is none: lexicon.nouns.Nouns.names_no_thing)
        if (
            w not in _SELVES
            and w not in DETERMINERS
            and set(getAllLemmas(w)) == {"NOUN"}
            and names_a_thing(w)
            and not nouns().names_no_thing(w)
        ):
            return w
    return None


def _plain(sentence: str) -> str:
    """Lower case, and a courtesy before the verb gone ("please turn on the stove": a request said with a verb)."""
    text = sentence.lower().replace("\u2019", "'").strip()
    text = re.sub(r"^(?:(?:please|kindly|ok|okay|now|so|and|then|robot),?\s+)+", "", text)
    # asked as a question ("could you put ...", "would you mind putting ..."): the request's own verb
    text = re.sub(r"^(?:could|can|would|will) you (?:please |kindly )?(?=\w)(?!mind\b)", "", text)
    minded = re.match(r"(?:would|do) you mind (\w+ing)\b", text)
    lemma = getAllLemmas(minded.group(1)).get("VERB") if minded else None
    return lemma[0] + text[minded.end() :] if minded and lemma else text


def context_sentences(instruction: str, found: list[str], says_a_goal: Callable[[str], bool]) -> tuple[str, list[str]]:
    """The instruction without the sentences that only set the scene for it ("okay so this one's pretty simple, i
    think.", "we're checking the grasp again today."): none starts with a verb, says a goal (`says_a_goal`), names
    a thing perception found or the scene holds, names a thing it lacks, or points at one ("it");
    the instruction and no sentences when none is such or nothing else is left."""
    said = [t.strip() for t in re.split(r"(?<=[.!?;])\s+", instruction.strip()) if t.strip()]
    known = {w for p in found for w in re.findall(r"[a-z]+", p.lower())}
    aside = [
        t
        for t in said
        if not starts_with_verb(_plain(t))
        and not says_a_goal(t)
        and not set(re.findall(r"[a-z]+", _plain(t))) & (known | {"it", "them"})
        and names_absent(t, found) is None
    ]
    if not aside or len(aside) == len(said):
        return instruction, []
    return " ".join(t for t in said if t not in aside), aside


# A sentence that only says a thing is there (and where): "there's a handle on the cabinet drawer."
_THERE = re.compile(
    r"(?:there(?:'s| is| are)|here(?:'s| is| are)) (?:a|an|the|one|two|three|some) (?:[a-z]+ ){0,3}?[a-z]+"
    r"(?: (?:on|in|inside|at|by|next to|beside|near|under|behind|in front of|on top of) (?:the|a|an) (?:[a-z]+ ){0,3}?"
    r"[a-z]+)?\s*[.!]?"
)
_SAYS_MORE = re.compile(r"\b(?:that|which|who|goes|go|should|needs?|wants?|must|belongs?|has to|have to)\b")


def only_what_is_there(instruction: str) -> bool:
    """Every sentence of `instruction` only says that a thing is there: a statement with nothing asked of it."""
    said = [t for t in re.split(r"(?<=[.;!?])\s+", instruction.strip().lower()) if t]
    return bool(said) and all(_THERE.fullmatch(t) and not _SAYS_MORE.search(t) for t in said)
