"""An instruction as imperative clauses: politeness and trailing clauses dropped, a goal stated as a state or a
wish ("the apple belongs in the bowl", "I'd like the stove on", "tray: both cups") turned into the action that
makes it true, and a purpose that names the destination ("... so that it sits in front of the lamp") kept."""

from __future__ import annotations

import re
from collections.abc import Callable

from lemminflect import getAllLemmas, getLemma

from ...perception.variants import PARTS
from .briefings import plain_briefing
from .lexicon import (
    CONTAINERS,
    CONTENTS,
    CONTENTS_SAID,
    COPULAS,
    DIRT,
    FILLERS,
    HELD,
    HOLDS,
    MODALS,
    PARTICIPLES,
    SPEAKERS_PLANS,
    SPEAKERS_REASON,
    STATE_ACTIONS,
    SUBSTANCES,
    VERBS,
)
from .names import compound_names
from .phrases import singular
from .qualify import qualify
from .things import adverb_only, is_thing, is_verb

CONTRACTIONS = {
    "there's": "there is",
    "here's": "here is",
    "it's": "it is",
    "that's": "that is",
    "i'd": "i would",
    "i'm": "i am",
    "you'll": "you will",
    "you'd": "you would",
    "let's": "let us",
    "don't": "do not",
    "doesn't": "does not",
    "isn't": "is not",
    "aren't": "are not",
    "wasn't": "was not",
    "you're": "you are",
    "we're": "we are",
    "they're": "they are",
    "i've": "i have",
    "you've": "you have",
    "we've": "we have",
    "i'll": "i will",
    "we'll": "we will",
    "it'll": "it will",
    "that'll": "that will",
    "won't": "will not",
    "can't": "cannot",
    "shouldn't": "should not",
    "mustn't": "must not",
    "needn't": "need not",
    "what's": "what is",
    "where's": "where is",
    "he's": "he is",
    "she's": "she is",
}
ACTION_WORDS = {
    "pick": "pick up",
    "put": "put",
    "stack": "stack",
    "push": "push",
    "open": "open",
    "close": "close",
    "turn_on": "turn on",
    "turn_off": "turn off",
    "scrub": "scrub",
    "pour": "pour",
}
_VERB_FORMS = sorted({f for forms in VERBS.values() for f in forms} | {"turn", "switch", "use", "there is"}, key=len)
_FIRST_WORDS = {f.split()[0] for f in _VERB_FORMS}
_TRAILING = re.compile(
    r"(?:\s*[,:]\s*|\s+-+\s+|\s+)(?:and\s+)?(?:then\s+)?(?:just\s+|simply\s+)?"
    r"(?:keep|keeping (?:it|them)|hold(?= (?:it|them|still|steady|on|up|there)\b)|make sure|"
    r"let go|release|stop|ensure|check|wait|let (?:it|them)\b|"
    # how to hold it, said after the action ("..., holding it by its two handles")
    r"(?:while )?(?:holding|gripping|grasping|grabbing) (?:it|them)\b|"
    r"(?:put|set|place) (?:it|them) back|leaving\b|"
    r"leave (?:it|them)\b(?!.*\b(?:on|in|into|onto|inside) (?:the|a|an)\b)|"
    # the things not moved stay as they are ("... and leave the rest where they are", "..., leave the bowl as it is")
    r"leave (?:the rest|everything else|the others?|all else|the [\w ]+? (?=where|as|alone|be\b))(?: of them)?"
    r"\s*(?:(?:where (?:it is|they are)|as (?:it is|they are)|alone|be))?\s*$|"
    # when or how fast, not what or where ("... when you get a chance", "... in one go", "..., nice and slow")
    r"(?:(?:when|whenever) you (?:get|have got|have|find) (?:a |the )?(?:chance|moment|minute|sec|second|time)|"
    r"(?:when|whenever) you (?:can|are ready)|if (?:you can|possible)|asap|no (?:rush|hurry)|"
    r"in (?:one|a single) (?:go|motion|move|movement|piece)|nice and (?:slow|easy|gentle|steady|gently|slowly))\s*$|"
    # what the speaker will do after ("..., i'll heat it later")
    r"(?:i|we) (?:will|shall|am going to|are going to|can) \w+ (?:it|them)(?: \w+)?$|"
    # when the speaker comes back, after the goal ("... when i get back", "... before we arrive")
    r"(?:when|before|by the time|until|once) (?:i|we) (?:get|come|am|are|return|arrive|walk)\b|"
    # how gently, before why ("..., nice and gently so it stays in")
    r"nice and(?: (?:slow|easy|gentle|steady|gently|slowly))?(?= so\b|\s*$)|"
    # how to do it or a check on the result, said after the action ("..., making sure it ends up inside",
    # "..., taking care not to tip it", "... without knocking anything over", "... rather than on the rim")
    r"(?:while |by )?(?:making sure|ensuring|checking|being careful|taking care|careful|trying|try to|try and|"
    r"try not to|without|"
    r"rather than|"
    r"instead of|as (?:gently|carefully|slowly) as)|"
    # the request closed ("..., blue block to the yellow tray, done")
    r"(?<=,)\s*(?:and )?(?:done|finished|over|end|fin)\s*$|"
    # how thoroughly a cleaning goal is met ("table free of dirt, every last speck", "..., not a crumb left")
    r"(?:every|each|evry) (?:last |single )?(?:speck|bit|crumb|trace|spot|smudge)(?: of (?:it|the \w+|\w+))?"
    r"(?: gone| removed| off| cleaned| wiped)?\s*[.!]?$|"
    # a setting that does not matter, after the switch ("crank the hob on, low is fine")
    r"(?:low|high|medium|max|min|any|whatever)(?: heat| setting| power| level)? (?:is|'s) (?:fine|ok|okay|good)"
    r"\s*[.!]?$|"
    # how it lies once set down ("butter into the basket, lay it flat")
    r"(?:lay|lie|set|keep|leave|place|put) (?:it|them) (?:down )?(?:flat|level|upright|on its side|on their side)"
    r"\s*[.!]?$|"
    r"not (?:a|one|a single) (?:speck|bit|crumb|trace|spot|smudge)(?: left| remaining)?\s*[.!]?$|"
    # the cleaning goal said again ("table clean, no dirt left")
    rf"no {DIRT} (?:left|remaining|anywhere|on it|on the \w+)\b|"
    # the means, after the step it serves ("switch the stove on by twisting the knob")
    r"by (?:twisting|turning|rotating|flicking|flipping|pressing|pushing|pulling|tugging|using|working|spinning|"
    r"cranking|sliding|lifting|gripping|grabbing|holding|tipping|tilting)\b|"
    # how, against how not ("..., sliding it rather than lifting", "... pushing them, not carrying them")
    r"[a-z]+ing (?:it|them),? (?:rather than|instead of|as opposed to|and not|but not|not|without|never)\b|"
    # a remark to the listener, not a step ("..., then you are done", "..., that is all", "that is the goal")
    r"(?:you|we|i) (?:are|am|will be|should be) (?:done|finished|all set|good)|"
    # when the goal should hold, said after it ("... by the end", "... when you are done", "... at the end")
    r"(?:by|at|in) the end\b|by the time\b|"
    r"(?:when|once) (?:you are|you have|it is|that is|we are) (?:done|finished|through)\b|"
    # a step that only takes the arm away, or a don't: no thing moves ("... and then go back to where you
    # started", "... and move your arm out of the way", "... and do not squash it")
    r"(?:go|come|head|return|get) (?:back|home)\b|move (?:your|the) (?:arm|gripper|hand)\b|(?:do not|never) |"
    r"(?:send|bring|take|move|return) (?:the |your )?(?:arm|robot|gripper|hand) (?:back )?(?:home|away|back)\b|"
    # a reason or a need of the speaker's after the request ("..., since it's going back to the fridge", "..., i
    # need to get at what's inside"), the action said again to say how ("- just push it, don't pick it up"),
    # how carefully ("..., carefully so the stack doesn't tip")
    r"(?:since|because|as) (?:it|they|that|this|i|we|you)\b|"
    r"(?:i|we) (?:need|want|have) to (?:get|reach|see|look|check)\b|"
    rf"{SPEAKERS_PLANS}|{SPEAKERS_REASON}|"
    r"(?:just |simply |only )(?:push|slide|shove|nudge|move) (?:it|them)\b|"
    r"(?:carefully|gently|slowly)\b(?= so\b|\s*$)|"
    # the goal's own name after it ("..., that is the end state i am after", "not the other way round")
    # ("..., that is my wish", "...: that is the target state", "..., that is what i am wanting")
    r"(?:that|this) (?:is|will be|would be) (?:the|my|our|this (?:scene|run|task|trial)'s) "
    r"(?:(?:target|goal|end|final|desired) )?(?:end state|"
    r"final state|result|outcome|state|arrangement|one|target|aim|idea|goal|wish|hope|plan|request|picture|"
    r"deliverable|point|ask|task|job|assembly|setup|configuration|layout)\b|"
    r"(?:this|that) (?:is what )?(?:i|we) (?:want|need|would like|am after|are after|mean)\b|"
    r"(?:and )?not the other way\b|that is what (?:i|we) (?:am |are )?(?:after|wanting|needing|hoping for)\b|"
    r"that is what (?:i|we) (?:want|need|mean|would like|am asking for|are asking for)\b|"
    # a courtesy or a remark about how things came to be ("..., if you would", "..., ta", "..., someone left it
    # open"), which side faces up ("..., flat side down"), or moving the arm away ("..., then move back")
    r"if you (?:would|could|can|do not mind|please)\b|ta$|cheers$|"
    # how a lifted thing ends up, after the goal ("red cube up in the air, held (in the gripper)")
    r"(?<=, )held(?: (?:in|by) (?:the|your) (?:gripper|hand|fingers))?$|"
    r"(?<=, )(?:held |lifted |raised |up )?(?:clear of|clear off|up off|above) the (?:table|surface|tabletop|counter)$|"
    # an adjustment of where it already is ("..., and get it centred", "... nice and level")
    r"(?:get|have) (?:it|them) (?:(?:properly|really|nice and|nicely|good and) )?(?:centred|centered|straight|level|"
    r"aligned|lined up|square|clean|spotless|shiny|tidy|sparkling)\b|"
    # a finer point of where, after the destination was said ("..., get it near the middle of the plate")
    r"(?:get|have|keep|put|set|leave) (?:it|them) (?:(?:roughly|about|approximately|around|somewhere|more or less|"
    r"right|just|nicely) )?(?:near|in|at|towards?|to|by|in the direction of) the "
    r"(?:middle|centre|center|edge|side|front|back)\b|"
    r"(?:someone|somebody|i|we|they|you) (?:left|put|moved|knocked|dropped) (?:it|them)\b|"
    # how it is set down ("..., and set it down flat so that it doesn't slide")
    r"(?:and )?(?:set|put|lay|place) (?:it|them) down(?: (?:flat|gently|carefully|upright|straight|softly))?"
    r"(?= so\b|\s*$)|"
    # how far down it goes ("..., all the way down so that it sits flat"), one to a place ("..., one block per tray")
    r"(?:all the way|fully|right) (?:down|home|on)\b|"
    r"one (?:\w+ )?(?:per|in each|to each|for each|in every) (?:tray|bowl|bin|plate|basket|peg|box)\b|"
    # how far, if it can ("open it, all the way if it will go"), how many strokes ("..., a few passes")
    r"(?:all the way |fully |as far as )?if it (?:will|can|would|does) go\b|"
    r"(?:a few|several|some|two|three|a couple of|a couple) (?:passes|strokes|swipes|rubs|wipes|times)\b|"
    # why, said of the task ("..., because the push is what we are testing")
    r"(?:since|because) the (?:push|pull|grasp|lift|pour|scrub|wipe|test|point|idea|goal|trial|run|place|grip)\b|"
    # how it came to be so ("... is sticking out from the last test")
    r"(?:from|since|after) (?:the |our |my )?(?:last|previous|earlier|other|yesterday's) (?:test|run|trial|time|"
    r"session|episode|attempt|task|one|round)\b|"
    r"(?:\w+ )?side (?:up|down)$|move (?:back|away)$|"
    # which way up it stands: no object, no place ("..., right side up", "... upside down")
    r"(?:(?:the )?(?:right|correct) (?:side|way) up|upside down|upright|standing(?: up| upright)?)(?=\s*$)|"
    r"that (?:is|will be|should be) "
    r"(?:all|it|everything|the (?:goal|plan|idea|task|job|aim))|that is all|thanks?(?: you)?)\b.*$"
)
# Words said of small contents ("some little beads"): what they are is still the contents.
_SMALL = r"(?:(?:little|tiny|small|loose|few|coloured|colored|glass|plastic) )*"
# Surfaces said as a verb ("plate the bowl": put it on the plate).
_SURFACES = ("plate", "saucer", "shelf", "rack")
# Where to grip it is no object and no place: "pick up the mug by its handle" picks up the mug.
_GRIP = re.compile(r"\s+by (?:its|the|their) (?:two |both )?(?:handles?|grips?|rims?|edges?)\b")
# a place ruled out after the one given ("put the bowl on the plate, not on the stove"): the place said stands
_NOT_THERE = re.compile(
    r",\s*(?:and |but )?not (?:on|in|into|onto|inside|on top of|next to|beside|near) (?:the|a|an) .*$"
)
_PURPOSE = re.compile(r"(?:\s*,\s*|\s+)(?:so(?: that)?|in order that|until|till)\s+(.*)$")
_PURPOSE_PLACE = re.compile(
    r"\b(?:sits?|is|are|ends? up|rests?|lands?|stays?|goes|fall|falls|drops?|lies|lie|"
    r"(?:is |are )?(?:sitting|resting|lying))\s+"
    r"(in front of|next to|beside|inside|into|within|in|on top of|onto|on)\s+(.+)$"
)
_DESTINATION = re.compile(r"\b(in front of|into|onto|inside|in|on top of|on|to|over)\b")


def starts_with_verb(text: str) -> bool:
    first = text.split(" ", 1)[0]
    return first in _FIRST_WORDS and any(text == f or text.startswith(f + " ") for f in _VERB_FORMS)


def sentences(instruction: str) -> list[str]:
    """Lower case, contractions spelled out, fillers gone; one string per sentence."""
    text = instruction.lower().replace("’", "'").strip()
    # "the blue block is first (the base)": in a stack, the first one is the bottom, the base only says so again
    text = re.sub(r"\bfirst,? \(?(?:as |at )?the (?:base|bottom|foundation)\)?", "at the bottom", text)
    text = re.sub(r"\s*[()]\s*", " ", text).strip()  # "(carefully)", "(thanks)": an aside's words, read as said
    text = plain_briefing(text)  # learners' and operators' wording (rules/briefings.py)
    # a ramekin by its cook's name ("the little souffle dish"): a compound whose head names another kind (a cup)
    text = re.sub(r"\bsouffl[eé] (?:cup|dish|pot|mould|mold)(s?)\b", r"ramekin\1", text)
    # a bowl by what is eaten from it ("the white soup dish", "the cereal bowl"): a bowl (a "fruit bowl" or a "salad
    # bowl" may be a kind of its own, which a scene without one lacks)
    _served = r"\b(?:soup|cereal|pasta|noodle) "
    text = re.sub(_served + r"(?:dishes|bowls)\b", "bowls", re.sub(_served + r"(?:dish|bowl)\b", "bowl", text))
    text = compound_names(text)  # "the hot plate": the stove (rules/names.py)
    # "whichever block is neither green nor blue": the block that is neither (a relative clause, said without "that")
    text = re.sub(r"\bwhichever ((?:[a-z]+ ){0,2}?[a-z]+) (is|are) (?=neither\b|not\b)", r"the \1 that \2 ", text)
    # speech: "um", "uh", and a phrase said twice around one ("in the, uh, in the basket")
    text = re.sub(r",?\s*\b(?:um+|uh+|erm|er|hmm+)\b,?", "", text).strip(" ,")
    # (not a chain of places: "the red block on the green block, the green block on the blue block")
    text = re.sub(r"\b((?:\w+ ){1,2}\w+),? \1\b(?!,? (?:on|onto|in|into|inside|on top of) )", r"\1", text)
    # a correction said aloud, then the request said again in a sentence of its own ("put the ketchup in the b-- no
    # wait, not the ketchup, the milk. milk in the basket"): what came before the correction is taken back
    text = re.sub(
        r"^.*?(?:\b\w*-+\s*|\b)(?:no wait|wait no|no no|scratch that|actually no|sorry,? i mean)\b[,.]?\s*"
        r"(?=[^.;!?]*[.;!?]\s*\w)",
        "",
        text,
    )
    text = re.sub(r"[!?]+(?=\s*,)", "", text)  # "the wine bottle, not the bowl!, should go ...": one sentence
    # "grab the bowl to the right of the box and put it on the plate": it is carried to the plate, so the side said
    # first is where it is (as "sitting to the right of" says), not a place it goes
    text = re.sub(
        r"\b((?:grab|take|pick up|pick|lift|get|grasp|fetch|collect|seize) (?:the|a|an) [a-z ]+?) "
        r"(?=(?:just |right |directly )?to the (?:left|right)(?:[- ]hand)?(?: side)? of (?:the|a|an) [a-z ]+?,? "
        r"(?:and|then)(?: then)? (?:\w+ ){1,2}(?:it|them)\b)",
        lambda m: m.group(0) if re.search(r"(?:ing|ed|is|are)$", m.group(1)) else f"{m.group(1)} sitting ",
        text,
    )
    # "slid along the table until it rests in front of the stove": the surface it moves on, before where it goes
    text = re.sub(
        r"\s+(?:along|across|over) the (?:table|tabletop|table top|surface|counter|worktop)\b"
        r"(?=\s+(?:until|till|to|towards?|into|onto|so)\b)",
        "",
        text,
    )
    # "grasp the cube and raise the end-effector": the robot's own part raised with the thing in it lifts the thing
    text = re.sub(
        r"(?<=\band )(?:raise|lift|move up|bring up) (?:the |your |its )?(?:end[- ]?effector|gripper|arm|hand|wrist)"
        r"(?: up)?\b(?! of\b)",
        "lift it",
        text,
    )
    # where the gripper takes hold ("grasp the wine bottle by the neck"): how it is held, no thing of the scene's
    text = re.sub(
        r"\b((?:grasp|grab|grip|hold|take|pick up|lift|seize|catch)(?: up)? (?:the|a|an|it|that) ?[a-z ]*?) by "
        r"(?:the|its) (?:neck|rim|lip|cap|top|base|body|middle|sides?|edges?|corners?|waist|shoulder)\b",
        r"\1",
        text,
    )
    for short, long in CONTRACTIONS.items():
        text = re.sub(rf"\b{re.escape(short)}", long, text)
    # "... in the white bowl instead": the goal replaces how things are, no word of it
    text = re.sub(r",?\s+instead\s*(?=[.!]?$)", "", text)
    # "goes up on top of the cabinet", "ought to be up on the shelf": "up" says only that the place is high
    text = re.sub(r"\b(goes|go|be|is|are|sits|sit|belongs|belong) up (?=(?:on top of|onto|on to|on)\b)", r"\1 ", text)
    # "... in the bowl instead of the mug": the place it is now, ruled out, no place of the goal's
    text = re.sub(
        r",?\s+(?:instead of|rather than) (?:the|a|an|that) (?:(?!(?:and|then|in|on|into|onto|to|it)\b)[a-z]+ ?){1,3}"
        r"\s*(?=[.!]?$)",
        "",
        text,
    )
    # "when that's steady, add ...": the step before is done, then the next
    text = re.sub(
        r"(^|[.;]\s+)(?:when|once|after) (?:that|it|this|they)(?: is| has| are|'s)? "
        r"(?:steady|stable|done|finished|in place|settled|there|placed|down|balanced|secure)\s*,?\s*",
        r"\1then ",
        text,
    )
    # "the bowl that is not already beside the plate": "already" says it is so now, no word of where
    text = re.sub(
        r"\balready (?=(?:on|in|inside|beside|next to|by|near|at|sitting|resting|on top of|there)\b)", "", text
    )
    # "the one resting on the cookies": where "one" is, said by how it lies
    text = re.sub(
        # (not "the plate's the one sitting on the box", which says which plate)
        r"(?<!\bis the )(?<!'s the )\b(one|ones) (?:that is |which is |that's )?"
        r"(?:resting|sitting|lying|standing|placed|perched|parked) "
        r"(?=(?:on|in|at|by|near|next to|beside|inside|on top of)\b)",
        r"\1 ",
        text,
    )
    # "only the plate goes ...", "put only the butter in ...": "only" says nothing else goes
    text = re.sub(r"\bonly (?=(?:the|a|an)\b)", "", text)
    # "leave everything else on the table and ...": the rest stays, no step
    text = re.sub(
        r"(^|[.;]\s+)(?:leave|keep) (?:everything|anything|all|the rest)(?: else)?"
        r"(?: (?:on the table|where it is|where they are|alone|as it is|as they are|in place|untouched|be))?"
        r"\s*(?:,|;|\.|\band\b)\s*",
        r"\1",
        text,
    )
    # a wish said as a condition ("it would be great if the stove were on"): the state wished for
    text = re.sub(
        r"^it (?:would|will|'d) be (?:great|nice|good|lovely|ideal|perfect|awesome|brilliant|helpful) if "
        r"((?:the|a|an|both|all) [a-z' ]+?) (?:were|was|is|are|could be|would be|got|ended up|end up) ",
        r"\1 should be ",
        text,
    )
    # how a thing is set down, said between it and the place ("lay it flat on top of the cabinet"): no word of either
    text = re.sub(
        r"\b(it|them) (?:flat|upright|level|straight|down|gently|carefully|softly|neatly) "
        r"(?=(?:on|in|onto|into|on top of|inside|down on|down in)\b)",
        r"\1 ",
        text,
    )
    # "the black bowl just to the right of the box": "just" only says how near
    text = re.sub(
        r"(?<=[a-z]) just "
        r"(?=(?:to the (?:left|right) of|next to|beside|behind|in front of|by|near|above|below|under)\b)",
        " ",
        text,
    )
    # a place, then the thing said as "with it" ("onto the plate with it"): the thing put there
    text = re.sub(
        r"(^|[.;!?]\s+)(onto|into|on to|on top of|in|on|inside) ((?:the|a|an) [a-z' ]+?) with (it|them|that)\b",
        r"\1put \4 \2 \3",
        text,
    )
    # a warning before the goal's list ("don't mix them up: the red block goes ..."): no part of the request
    text = re.sub(
        r"^(?:do not|don't|dont) (?:mix|get|muddle|jumble) (?:them|these|those|it|the two|things) "
        r"(?:up|wrong|confused|around)\s*[:,;-]+\s*",
        "",
        text,
    )
    # the speaker's hedge before what they want ("i think the drawer should be open, can you ..."): the wish itself
    text = re.sub(
        r"(^|[.;!?]\s+)i (?:think|guess|believe|reckon|suppose|feel like)(?: that)?,?\s+"
        r"(?=(?:the|a|an|it|this|that|you|we|both|all)\b)",
        r"\1",
        text,
    )
    # "straight ahead", "from where it sits": how and whence it moves, no word of the thing or the place
    text = re.sub(r"\bstraight (?=(?:ahead|forwards?|backwards?|back|away|into|onto|toward|towards)\b)", "", text)
    text = re.sub(r"\s*\bfrom where (?:it|they) (?:is|are|sits?|stands?|lies|lie|rests?)(?: now)?\b", "", text)
    # a clean surface wished for without a verb ("a clean table, no dirt left on it"): the wish, said
    text = re.sub(r"^(?:a|an) (?=(?:clean|spotless|tidy|dirt-free|dust-free) \w)", "i want a ", text)
    # ... and no dirt left on it: the wish on its own, or said again after it
    dirt = rf"no {DIRT}(?: at all)? (?:left )?on"
    text = re.sub(rf"^{dirt} (the \w+)(?=\s*[.!]?$)", r"wipe \1", text)
    text = re.sub(rf",\s*{dirt} (?:it|the \w+)\s*(?=[.!]?$)", "", text)
    # when, said of this request only ("don't touch the soup this time, ..."): no thing's word and no step
    text = re.sub(r",?\s*\b(?:this time|for once|for today|this once|(?:just )?for the moment)\b", "", text)
    # thanks as it is texted ("... in the basket thx"): a courtesy, said plainly so that it closes the request
    text = re.sub(r"\b(?:thx|thnx|thnks|thanx|thks|tyvm)\b", "thanks", text)
    text = re.sub(r"\bfwd\b", "forward", text)  # a direction as it is texted ("push it fwd")
    # "when ur done the drawer should be ...": the end of the task, said of the goal that follows
    text = re.sub(
        r"^(?:when|once) (?:you(?:'re| are| r)?|ur|u r|you're) (?:all )?(?:done|finished),?\s+(?=the\b)", "", text
    )
    # "i need the drawer standing open": how a thing wanted stands, said of its state
    text = re.sub(
        r"\b(need|want|like|get|keep) (the [a-z ]+?) (?:standing|sitting|left|lying|hanging) (open|shut|closed)\b",
        r"\1 \2 \3",
        text,
    )
    # "the drawer should be open with the block (sitting) in it": the opening, then the carry into it
    text = re.sub(
        r"\b(the [a-z ]+?) (?:should be|must be|needs to be|is to be|has to be) (?:left )?(?:open|opened|pulled out|"
        r"pulled open|slid out) with (the [a-z ]+?) (?:sitting |resting |placed |put |lying )?(in|inside) it\b",
        r"open \1, then put \2 in it",
        text,
    )
    # "..., up top": where the place is, said again after it ("top" alone is a place of its own)
    text = re.sub(r",\s*(?:up top|down below|down low|up high)\s*(?=$|[.!,;])", "", text)
    # "the mug's got beads in it": the mug has them, not whose
    text = re.sub(r"(\w)'s got\b|\bhas got\b", lambda m: f"{m.group(1) or ''} has".lstrip(), text)
    # an interjection or a turn-taking word said first ("hey, ...", "um ...", "next: ..."): no part of the request
    text = re.sub(
        r"^(?:(?:hey|hi|hello|oi|yo|um+|uh+|hmm+|erm?)(?: there| robot| buddy| mate)?\b[,!.]?\s*|"
        r"(?:next(?: up| one)?|and next)\s*:\s*)+",
        "",
        text,
    )
    # "when you get a moment, could ...": when it is wanted, said first
    text = re.sub(
        r"^(?:when|whenever|once) you (?:get|have got|have|find) (?:a |the )?(?:chance|moment|minute|sec|second|"
        r"time)\b,?\s*(?=\w)",
        "",
        text,
    )
    # "(hmm) ok, so the beads should ...": a turn-taking "ok, so" before the request
    text = re.sub(r"^(?:ok|okay|alright|right)(?:,)? so\b,?\s*", "", text)
    for said, plainly in _SPOKEN_PLAINLY + _HOW_PLAINLY:
        text = re.sub(said, plainly, text)
    text = _apposed_look(text)
    # "red cube up off the table, please": a lift said by where the thing ends up
    text = re.sub(
        r"^((?:the |a |an )?[a-z]+(?: [a-z]+){0,2}) up(?: (?:off|from) (?:of )?(?:the )?(?:table|counter|surface))?"
        r"(?=\s*(?:[.;!?]|,\s*(?:please|holding)\b|$))",
        lambda m: m.group(0) if _verb_first(m.group(1)) else f"pick up {m.group(1)}",
        text,
    )
    # a thing held up "off the table" / "clear of the table": where it was lifted from, not another place; "grasped
    # and lifted" is lifted
    text = re.sub(
        r"\b(up|lifted|raised|held|grasped|picked up|hoisted)\s+(?:up )?(?:off|clear of|above|from|away from) "
        r"(?:the )?(?:table|tabletop|table top|counter|surface)\b",
        r"\1",
        text,
    )
    text = re.sub(r"\b(?:grasped|gripped|grabbed|held|taken) and (lifted|raised|held up|picked up)\b", r"\1", text)
    # a switch worked by a verb of its own and the state after the thing ("flick the hob on", "shut the gas off")
    text = re.sub(
        r"(^|, |\band |\bthen |[-—:] )(?:flick|flip|click|shut|knock|whack|put|set|crank) "
        r"((?:the|a|an) [\w ]+?|it|them) (on|off)"
        r"(?=\s*(?:$|[,.;!?]|\band\b|\bthen\b|\bfor (?:me|us)\b|\bplease\b))",
        r"\1turn \3 \2",
        text,
    )
    # "get the drawer open and the red block in it": the verb said once for a state and a carry
    text = re.sub(
        r"\b(get|have) ((?:the|a|an) [\w' ]+?) (open|opened|closed|shut|switched on|switched off|turned on|turned off) "
        r"and ((?:the|a|an) [\w ]+?) "
        r"(?=(?:in|into|inside|on|onto|on top of) (?:it|the|a|an)\b)",
        r"\1 \2 \3 and put \4 ",
        text,
    )
    # a state brought about ("get the drawer open and ...", "have the stove switched on"): the action that makes it
    text = re.sub(
        r"(^|, |\band |\bthen )(?:get|have|make) ((?:the|a|an) [\w' ]+?) "
        r"(open|opened|closed|shut|switched on|switched off|turned on|turned off)(?=\s*(?:$|[,.;!?]|\band\b|\bthen\b))",
        lambda m: f"{m.group(1)}{ACTION_WORDS[dict(STATE_ACTIONS)[m.group(3)]]} {m.group(2)}",
        text,
    )
    # common slips of the keyboard: "teh", "ontop", "id like" (the apostrophe left out)
    text = re.sub(r"\bteh\b", "the", text)
    text = re.sub(r"\bontop\b", "on top", text)
    text = re.sub(r"^id (like|love|want)\b", r"i would \1", text)
    text = re.sub(
        r"\bi would (like|love)\b(?! you to)|\bi would (?:appreciate|prefer)\b(?! it\b| you\b)", r"i want", text
    )
    # the speaker as "we" ("we need the ketchup in the basket"): the same wish
    text = re.sub(
        r"\bwe (?:want|need|would like|would love)\b(?= (?:the|a|an|it|them|both|all|every|each)\b)", "i want", text
    )
    # apostrophes left out ("dont touch", "isnt", "youll need to")
    text = re.sub(r"\b(do|does|is|are|was|should|must)nt\b", r"\1 not", text)
    text = re.sub(r"\b(can)t\b|\bwont\b", lambda m: "cannot" if m.group(1) else "will not", text)
    text = re.sub(r"\byoull\b", "you will", text)
    # a wish without its subject ("want the cup on the saucer"), a request for the speaker ("can i get the cup in
    # the box"), a chance asked for ("any chance you could ..."), an obligation put on the listener ("you will need
    # to open it first"): the request itself
    text = re.sub(r"^(want|need)\b(?= (?:the|a|an|both|all) )", r"i \1", text)
    text = re.sub(
        r"^(?:can|could|may) (?:i|we) (?:get|have) "
        r"(?=(?:the|a|an) .+ (?:in|into|on|onto|inside|on top of) (?:the|a|an) )",
        "put ",
        text,
    )
    text = re.sub(r"^(?:is there )?any chance (?:you could |you can |you would |of you |that you could )?", "", text)
    text = re.sub(r"\byou (?:will |would |are going to )?(?:need|have|got|must) to\b", "", text)
    text = re.sub(r"\byou (?:will|would) (?:want to|wanna)\b", "", text)  # "first you'll want to open it"
    # "only the cheese goes in the basket": the one thing the goal names
    text = re.sub(r"^only (?=(?:the|a|an) )", "", text)
    # a wish said around the goal ("i'd love it if the ketchup ended up in the basket", "it would be great to have
    # the cup on the saucer"): the wish
    text = re.sub(
        r"\bi (?:would (?:love|like|prefer|appreciate)|want) it if ((?:the|a|an) [a-z ]+?) "
        r"(?:ended up|was|were|is|got|went|could go|could end up|would end up) "
        r"(?=(?:in|on|inside|into|onto|on top of|next to|in front of) )",
        r"i want \1 ",
        text,
    )
    text = re.sub(
        r"^it (?:would|will|might) be (?:great|nice|good|lovely|ideal|perfect|awesome|helpful|brilliant|cool) "
        r"(?:to (?:have|see|get) (?=(?:the|a|an) [a-z ]+? (?:in|on|inside|into|onto|on top of|next to) )|"
        r"if you (?:could |would |can )?(?=\w))",
        lambda m: "i want " if "to " in m.group(0) else "",
        text,
    )
    # "how about putting the ketchup in the basket?": the step suggested
    text = re.sub(
        r"^(?:how about|what about|why not try|maybe try|try) ([a-z]+ing)\b",
        lambda m: getLemma(m.group(1), "VERB")[0],
        text,
    )
    # "grab the bowl. the stove is where it should go": where the thing just named goes
    text = re.sub(
        r"(?<=[.;,] )((?:the|a|an) [a-z ]+?) is where (it|they) (?:should go|goes|go|belongs?|needs to go|has to go)\b",
        r"\2 goes to \1",
        text,
    )
    # "the rack is empty - fill it with the wine bottle": the thing it is filled with goes in it
    text = re.sub(r"\bfill (it|them|(?:the|a|an) [a-z ]+?) (?:up )?with ((?:the|a|an) [a-z ]+)", r"put \2 to \1", text)
    # "ketchup goes basket": the destination said without its preposition
    text = re.sub(
        r"^((?:the )?[a-z]+(?: [a-z]+)?) goes (?!(?:to|in|into|on|onto|inside|back|up|down|there|here|over|away)\b)"
        r"((?:the )?[a-z]+)\s*[.!]?$",
        r"\1 goes to \2",
        text,
    )
    # "red goes on green after that": when, said after the step, is the order the steps are said in
    text = re.sub(
        r",?\s*\b(?:after that|afterwards|after this|once that is done|when that is done)\s*(?=[.!]?$)", "", text
    )
    # "step 2: red block inside": a thing said with "inside" alone, after an opening, goes into what was opened
    text = re.sub(
        r"(?<=[.;!?] )((?:the )?[a-z]+(?: [a-z]+)?) (?:goes |should go )?inside\s*(?=[.!;]|$)",
        lambda m: (
            m.group(0)
            if starts_with_verb(m.group(1)) or not re.search(r"\bopen\b", text[: m.start()])
            else f"put {m.group(1)} inside"
        ),
        text,
    )
    # "..., can you do that", "..., go": the request is closed
    text = re.sub(
        r",?\s*(?:can|could|would|will) you (?:do|manage|handle) (?:that|this|it)(?: for me)?\s*\??$", "", text
    )
    text = re.sub(r",\s*go\s*[.!]*$", "", text)
    # "the bowl the cookies are next to": a thing by what stands beside it, the preposition left at the end
    text = re.sub(
        r"\b((?:the|a|an) [a-z]+(?: [a-z]+)?) (?:that |which )?(the [a-z]+(?: [a-z]+)?) (?:is|are|sits?|stands?) "
        r"(next to|beside|near|by)(?= (?:goes|go|should|needs|belongs|must|has|[,.;:-]|$)|[,.;:-]|$)",
        r"\1 \3 \2",
        text,
    )
    # "onto the green square just ahead of it": where the place is from the thing carried says nothing more
    text = re.sub(
        r"(\b(?:onto|into|on|in|to|toward|towards) (?:the|a|an) [a-z ]+?),? (?:just |right |directly |immediately )?"
        r"(?:ahead of|in front of|beyond|past|behind|beside|next to) (?:it|them)\b",
        r"\1",
        text,
    )
    # "slide the plate up against the stove's front": pushed to it
    text = re.sub(
        r"\b((?:slide|slides|push|pushes|shove|shoves|nudge|nudges|move|moves|scoot|scoots) (?:the |a |an )?[a-z ]+?) "
        r"(?:up |right |flush |snug )?against (?=the |its |their )",
        r"\1 to ",
        text,
    )
    # "the stove bowl", "the cabinet-top bowl": a thing named by the fixture it stands on
    # (or "the cabinet one" in a correction, and "the drawer bowl": in the drawer)
    text = re.sub(
        r"\bthe (stove|cabinet[- ]top|cabinet|cupboard|counter|shelf|rack|burner|hob|drawer) "
        r"(bowl|plate|mug|cup|pot|pan|bottle|box|block|cube|one)\b",
        lambda m: f"the {m.group(2)} {'in' if m.group(1) == 'drawer' else 'on'} the {m.group(1).replace('-', ' ')}",
        text,
    )
    # "..., the blue one must not move", "make sure the bowl isn't disturbed": the thing is left alone
    text = re.sub(
        r"(^|[,;.] |- |\bbut )(?:(?:make sure|ensure|check) (?:that )?)?((?:the|that|this) [a-z ]+?) "
        r"(?:(?:must|should|may|can|is to|are to)(?: not|n't)|(?:is|are)(?: not|n't)(?: to be)?)"
        r"(?: be)? (?:move|moved|touched|touch|disturbed|disturb|knocked over|bumped)\b(?: at all)?",
        r"\1leave \2 alone",
        text,
    )
    # "the red one needs lifting", "the drawer wants closing": the step said as what the thing needs
    text = re.sub(
        r"(^|[,;] |- )((?:the|that|this) [a-z ]+?) (?:needs|wants|could do with|requires) ([a-z]+ing)"
        r"( up| down| over| out)?\b",
        lambda m: (
            f"{m.group(1)}{getLemma(m.group(3), 'VERB')[0]}{m.group(4) or ''} {m.group(2)}"
            if m.group(3) not in ("nothing", "something", "thing", "everything")
            else m.group(0)
        ),
        text,
    )
    # "anything but the blue block - lift that": what "that" stands for is said first
    text = re.sub(
        r"^((?:anything|any one|any of them|whichever one|whatever)(?: one)? (?:but|except(?: for)?|other than) "
        r"(?:the|that) [a-z ]+?)\s*(?:-+|,|:)\s*(\w+(?: up)?) (?:that|it|that one|this one)\b",
        r"\2 \1",
        text,
    )
    # "everything stays where it is except the ketchup, which goes in the basket": the one thing and its goal
    text = re.sub(
        r"^(?:everything|all|the rest)(?: else)? (?:stays?|remains?|is staying)(?: where it is| put| as it is)?,? "
        r"(?:except|but|apart from|other than) (?:for )?((?:the|a|an) [a-z ]+?),? which ",
        r"\1 ",
        text,
    )
    # "the bowl, which goes on the plate": a goal said in a relative clause
    text = re.sub(
        r"^((?:the|a|an) [a-z ]+?),? which (?=(?:goes|should go|needs to go|has to go|belongs|must go) [^,]*$)",
        r"\1 ",
        text,
    )
    # "open the middle drawer - leave the top and bottom ones shut": the others of its kind left as they are
    text = re.sub(
        r"(?<=\w)\s*(?:,|;|\s-+)\s*(?:and |but )?(?:leave|keep) the (?:other |rest of the )?(?:[a-z]+ and [a-z]+ )?"
        r"(?:ones|one|others|drawers|drawer) "
        r"(?:shut|closed|alone|as (?:they|it) (?:are|is)|where (?:they|it) (?:are|is))\s*(?=[.!]?$)",
        "",
        text,
    )
    # "... and nothing else", "... though": the request is all there is
    text = re.sub(r",?\s*\b(?:and|but) nothing else\b", "", text)
    text = re.sub(r",?\s*\bthough\s*(?=[.!;]|$)", "", text)
    # "then red on the one you just placed": the thing put down last, as "that"
    text = re.sub(
        r"\bthe (?:one|block|cube|thing) (?:that )?(?:you|we|i)(?: have| 've)? (?:just |already )?"
        r"(?:placed|put down|put there|stacked|moved|set down|put)\b",
        "that",
        text,
    )
    # "the black bowl in the back is staying; put the front one ...": the thing said to stay is left alone
    text = re.sub(
        r"^((?:the|that|this) [a-z ]+?) (?:is|are) (?:staying|to stay|stays|remaining|to remain)"
        r"(?: (?:put|there|here|where (?:it is|they are)))?\s*(?=[;,.:]\s*\w)",
        r"leave \1 alone",
        text,
    )
    # a side of the table is the side ("the bowl at the front of the table"): the table is where everything is
    text = re.sub(
        r"\b(on|at|in) the (far |very )?(left|right|front|back|rear)(?: side| hand side| end| edge)? of the "
        r"(?:table|counter|workspace)\b",
        r"\1 the \2\3",
        text,
    )
    # "at the front of the stove" is "in front of" it
    text = re.sub(r"\bat the front of\b(?= (?:the|a|an) )", "in front of", text)
    # "the plate's sitting on the stove": "'s" before a participle of where a thing is, is "is"
    text = re.sub(r"(\w)'s (sitting|resting|standing|lying|located|kept|parked|perched|waiting)\b", r"\1 is \2", text)
    # "..., open the gripper", "then release your grip": letting go, which a carry does anyway
    text = re.sub(
        r"(?:\s*,\s*|\s+)(?:and\s+)?(?:then\s+)?(?:open|release|relax|loosen|let go of) (?:the |your )?"
        r"(?:gripper|grip|hand|fingers|claw|jaws)\b(?=\s*(?:$|[,.;!?]))",
        "",
        text,
    )
    # a list's closing status ("item complete.", "task done."): the request's frame, no step
    text = re.sub(
        r"(?<=[.;!?])\s*(?:checklist |task |job |item |step |procedure |order )?"
        r"(?:complete|completed|done|finished|over|over and out|out)\s*[.!]?\s*$",
        "",
        text,
    )
    # "... . hold it there.": holding still after a lift, said as a last sentence of its own, is what a lift ends in
    text = re.sub(
        r"(?<=[.;!?])\s*(?:and |then |now |just )?hold (?:it|them)(?: (?:there|still|steady|up|up there|in the air))?"
        r"(?: for a (?:moment|second|sec|bit|while))?\s*[.!]?\s*$",
        "",
        text,
    )
    # "lift it up toward the sky": up, said as where up leads
    # (not after a superlative: "the box closest to the ceiling" is the top one, qualify.py)
    text = re.sub(
        r"(?<!nearest )(?<!closest )(?<!nearer )(?<!closer )"
        r"\b(?:up )?(?:toward|towards|to) the (?:sky|ceiling|heavens|roof)\b",
        "up",
        text,
    )
    # "..., and nothing further.": the request said to be all there is
    text = re.sub(
        r"(?:,\s*(?:and )?|\s+and )(?:nothing|no more) (?:else|further|more|beyond that)\s*([.!]?)\s*$", r"\1", text
    )
    # "...; 3) release.", "... . let go of it": letting go said as a last sentence of its own, which a carry does
    text = re.sub(
        r"(?<=[.;!?])\s*(?:and |then |finally |lastly )?(?:release|let go)(?: (?:of )?(?:it|them))?\s*[.!]?\s*$",
        "",
        text,
    )
    # "fish it out", "scoop the bead out": taking it out of where it is
    text = re.sub(r"\b(?:fish|scoop|dig|lift) (it|them|(?:the|a|an) [\w ]+?) out\b", r"pick up \1", text)
    # "so the table's clear": "'s" before a state word is "is", not a possessive
    text = re.sub(
        r"(\w)'s (clear|empty|tidy|clean|free|full|done|ready|open|closed|shut|gone|level|straight)\b",
        r"\1 is \2",
        text,
    )
    # "build a stack for me - blue at the bottom, ...": the arrangement named, then its order
    text = re.sub(
        r"^(?:(?:would|could|can|will) you )?(?:build|make|form|put together) (?:a|the) (?:stack|tower|pile)"
        r"(?: for me)?\s*(?:[,:]|[-\u2013\u2014]+)\s*",
        "a tower: ",
        text,
    )
    # an arrow pointing back: "plate <- black bowl" is "black bowl -> plate"
    text = re.sub(r"^([^<]+?)\s*(?:<-|<=|\u2190|<--)\s*(.+)$", r"\2 -> \1", text)
    # "... -> done": the end of the steps said as one of them
    text = re.sub(r"\s*(?:->|=>|\u2192|-->)\s*(?:done|finished|finish|end|stop|complete)\s*[.!]*$", "", text)
    # "third drawer from the top -> open it": a thing, then the step done to it
    text = re.sub(
        r"^((?:the )?[a-z' ]+?)\s*(?:->|=>|\u2192|-->)\s*(open|close|shut|turn on|turn off|switch on|switch off|"
        r"pick up|lift|grab|push|wipe) (?:it|that one|that)\s*([.!]*)$",
        lambda m: f"{m.group(2)} {m.group(1) if m.group(1).startswith('the ') else 'the ' + m.group(1)}{m.group(3)}",
        text,
    )
    # "open drawer -> red block in": a thing and "in" after a step that opens is put in what was opened
    text = re.sub(
        r"^((?:open|pull open|pull out) (?:the )?[a-z ]+?)\s*(?:->|=>|\u2192|-->)\s*((?:the )?[a-z ]+?) "
        r"(?:in|inside|in there|in it)\s*([.!]*)$",
        lambda m: (
            m.group(0) if starts_with_verb(m.group(2)) else f"{m.group(1)}, then put {m.group(2)} in it{m.group(3)}"
        ),
        text,
    )
    # "open the top drawer -> put the cheese in it": an arrow before a step is "then"
    text = re.sub(
        r"\s*(?:->|=>|\u2192|-->)\s*(?=(?:put|place|set|move|take|grab|pick|open|close|turn|push|stack|"
        r"lift|pour|wipe|scrub|drop|shut)\b)",
        ", then ",
        text,
    )
    # "red block table -> bowl": the table said bare before the arrow is where the thing is now
    text = re.sub(
        r"\b(?!(?:the|a|an|from|on|off|of|at)\b)(\w+) (?:table|tabletop|counter)(?=\s*(?:->|=>|\u2192|-->))",
        r"\1 from the table",
        text,
    )
    # "cream cheese -> front of the stove": to a place beside a thing, not onto the thing
    text = re.sub(
        r"^(.*?)\s*(?:->|=>|\u2192|-->)\s*(?:to |in )?(?:the )?front of (?:the )?",
        lambda m: f"{'' if starts_with_verb(m.group(1)) else 'put '}{m.group(1)} to the front of the ",
        text,
    )
    # an arrow between a thing and a place: "green block -> basket" carries it there (a preposition after the
    # arrow says which way itself: "-> onto the plate")
    text = re.sub(
        r"\s*(?:->|=>|\u2192|-->)\s*(?:(into|onto|in|on|inside|on top of|to) )?(?:the |a |an )?([\w ]+)",
        lambda m: f" {_arrow_prep(m.group(1), m.group(2))} the {m.group(2)}",
        text,
    )
    # "then finish with the red block on top of that": the last step itself
    text = re.sub(
        r"\b(?:finish|end|top (?:it|things|the stack) off|cap (?:it|the stack) off)(?: off| up)? (?:with|by putting|by "
        r"placing) (?=(?:the|a|an) [\w ]+? (?:on top of|on|onto|in|into|inside)\b)",
        "put ",
        text,
    )
    # "start by putting green on blue": the step itself
    text = re.sub(r"^(?:start|begin)(?: off)? by (?=\w+ing\b)", "", text)
    text = _gerund(text)
    # "pick-and-place the cube onto ...": one carry
    text = re.sub(r"^pick[- ](?:and|&|n)[- ](?:place|drop|put)\b", "put", text)
    # "from the robot's point of view, ...": whose left and right, said first
    text = re.sub(
        r"^(?:(?:as )?(?:seen )?from|looking from) (?:the robot's|your|my|the robot|where you (?:stand|are))"
        r"(?: (?:point of view|perspective|side|view|position))?\s*,?\s*",
        "",
        text,
    )
    # "twist the stove's dial to the on position": a knob set to on or off
    text = re.sub(
        r"^(?:twist|turn|rotate|set|switch|put|flip) (.+?) (?:to|into) (?:the )?(on|off)(?: position| setting)?$",
        r"turn \2 \1",
        text,
    )
    # a remark that opens a turn in a conversation ("ok next one:", "alright,", "right then:")
    text = re.sub(r"^(?:ok|okay|alright|all right|right|so|now)(?: then)?(?:,? next(?: one)?)?\s*[:,]\s*", "", text)
    # "start with green on top of blue, then red on top of green": the first carry of a build
    text = re.sub(
        r"\bstart(?:ing)? (?:off )?(?:with|by putting|by placing|by setting) "
        r"(?=(?:the )?\w+(?: \w+)? (?:on top of|on|onto|in|into)\b)",
        "put ",
        text,
    )
    # "ketchup stays where it is": left as it is, said of the thing
    text = re.sub(
        r"(^|[.;!?,] )(?:the )?((?:\w+ ){0,2}?\w+) (?:stays?|remains?|(?:can|may|should|must|will) (?:stay|remain)) "
        r"(?:right |just |exactly )?(where (?:it is|they are)|as (?:it is|they are)|put)\b"
        r"(?: (?:on|at) the (?:table|counter)\b)?",  # "stays put on the table": where it is
        r"\1leave the \2 where it is",
        text,
    )
    # "push it so its in front of the stove": "it is" typed without the apostrophe before where it is
    text = re.sub(
        r"\b(so|till|until|then|and) its (?=(?:in|on|inside|next to|beside|near|at|sitting|resting)\b)",
        r"\1 it is ",
        text,
    )
    # "the cabinet's roof": its top
    text = re.sub(r"\bthe ((?:\w+ ){0,2}\w+)'s roof\b", r"the top of the \1", text)
    text = re.sub(r"\bthe roof of\b", "the top of", text)
    # "nah, not the bowl on the cookies": the "no" is the "not" that follows
    text = re.sub(r"^(?:nah|nope|naw|no),? (?=not\b)", "", text)
    # the goal said as the speaker's hope or aim ("my hope is that the butter ends up in the basket")
    text = re.sub(
        r"^(?:so,? )?(?:my|our|the) (?:hope|wish|aim|goal|plan|idea) (?:is|here is) (?:that |for )?", "i want ", text
    )
    # the goal said by what is wanted at the end ("what i want at the end: ...")
    text = re.sub(
        r"^(?:what|all) (?:i|we)(?:'d| would)? (?:want|need|like|hope|expect)(?: to see| to have| to find)?"
        r"(?: at the end| in the end| by the end| when you're done| when you are done| afterwards)?\s*[:,]\s*",
        "",
        text,
    )
    # "the cabinet top is where the plate goes", "the bowl closer to you is the one for the plate": a place named
    # first, then what goes there
    text = re.sub(
        r"^(.+?) is where (the .+?) (?:goes|go|belongs|should go|should be|needs to go|has to go)$",
        r"put \2 to \1",
        text,
    )
    # ("the one near the ramekin is the one i want on the plate", "... is what we need in the basket")
    text = re.sub(
        r"(^|[.;!?] )((?:the|a|an) [^.;!?]+?) is (?:(?:the one|what|the \w+(?: \w+)?) (?:that |which )?(?:i|we) "
        r"(?:want|need|would like|'d like)(?: to go| moved| put| placed| set)? (?:on|in|into|onto|to|on top of)|"
        r"the one (?:for|to go (?:on|in|into|onto|to)|(?:that is )?going (?:on|in|into|onto|to|on top of)|"
        r"(?:that |which )?(?:goes|belongs|should go|needs to go|has to go) (?:on|in|into|onto|to|on top of)))"
        r" (the [^.;!?]+?)(?=\s*[.;!?]|$)",
        r"\1put \2 to \3",
        text,
    )
    # "could the green block go into the basket?": a question whose subject is the thing moved
    text = re.sub(
        r"^(?:could|can|would|will) ((?:the|a|an) .+?) (?:go|be put|be placed|be moved|end up|get put) "
        r"(?=(?:in|into|on|onto|inside|on top of|to) )",
        r"put \1 ",
        text,
    )
    # a part worked for a purpose ("twist the knob on the stove to switch it on", "rotate the dial so as to turn
    # the burner off", "tug the handle to open the drawer"): the purpose is the step, done to what it names (or to
    # the part's own thing, which the planner finds the part of)
    text = re.sub(
        r"^(?:\w+)(?: \w+)? ((?:the|a|an) [\w' ]*?\b(?:knob|dial|handle|switch|lever|button|control)s?\b[\w ]*?),? "
        r"(?:so as |in order |so that you can |so you can )?to "
        r"(turn on|turn off|switch on|switch off|open|close|shut|"
        r"(?:turn|switch) (?=(?:it|them|the [\w ]+?) (?:on|off)$))"
        r" ?(it|them|(?:the|a|an) [\w ]+?)?( on| off| up| open| shut)?$",
        _part_purpose,
        text,
    )
    # a question that expects "yes" ("shouldn't the cheese be in the basket?", "isn't the bowl meant to be on the
    # plate?"): the goal it asks after, as a statement
    text = re.sub(
        r"^(?:is|are) not ((?:the|a|an) .+?) (?:supposed|meant|expected) to (?=(?:be|go|sit|end up) )",
        r"\1 should ",
        text,
    )
    text = re.sub(
        r"^(?:should|must|will|would|does|do) not ((?:the|a|an) .+?) (?=(?:be|go|belong|sit|end up) "
        r"(?:in|into|on|onto|inside|on top of|to|next to|beside|near)\b)",
        r"\1 should ",
        text,
    )
    # a phrasal verb split around its object ("fire the burner up", "power the stove on"), or a state brought
    # about ("get the hob going"): switching it on
    text = re.sub(r"^(fire|heat|power|switch|turn) ((?:the|a|an) [\w ]+?) (up|on)\b", r"\1 \3 \2", text)
    text = re.sub(
        r"(?:^|(?<=\byou )|(?<=\bplease )|(?<=\band ))get ((?:the|a|an) [\w ]+?) "
        r"(?:going|started|running|lit|fired up|heated up)\b",
        r"turn on \1",
        text,
    )
    # "the plate is to be slid until it rests in front of the stove": a push said in the passive, then where it ends
    text = re.sub(
        r"^((?:the|a|an) [a-z ]+?) (?:is|are|should be|must be|needs to be|has to be|is to be|are to be) "
        r"(?:pushed|slid|shoved|nudged)\b(?= (?:until|till|so|to|towards?|into|forwards?|backwards?|left|right)\b)",
        r"push \1",
        text,
    )
    # "make the stove stop being on": the state it is to leave, the other one brought about
    text = re.sub(
        r"\bmake ((?:the|a|an) [\w ]+?) (?:stop|quit) being (on|off)\b",
        lambda m: f"turn {'off' if m.group(2) == 'on' else 'on'} {m.group(1)}",
        text,
    )
    # "the bowl on the burner goes to the plate": a goal verb after a thing named without its article
    text = re.sub(
        r"^(?!the |a |an )([a-z][\w ]+?) (?:goes|belongs|should go) (?=(?:to|onto|into|on|in|inside|on top of) )",
        lambda m: m.group(0) if starts_with_verb(m.group(1)) else f"put {m.group(1)} ",
        text,
    )
    # "grab it and pull until the drawer is open", "push it until the drawer is shut": the drawer's end state
    text = re.sub(
        r"\b(?:(?:grab|grip|take hold of|hold|seize|catch) (?:it|the [\w ]+?) and )?(pull|push|slide)(?: it| on it)?"
        r"(?: out| in| back)? (?:until|till|til) ((?:the|its) [\w ]+?) (?:is|comes|slides) "
        r"(?:fully |all the way |right )?(open|out|closed|shut|in)\b",
        lambda m: f"{'open' if m.group(3) in ('open', 'out') else 'close'} {m.group(2)}",
        text,
    )
    # "(would you) mind opening the drawer": the gerund after "mind" is the request
    minded = re.sub(r"^(?:would you |do you )?mind (\w+ing)\b", lambda m: _lemma_verb(m.group(1)), text)
    if minded != text:  # "... and putting the red block inside": the steps after it said as gerunds too
        minded = re.sub(
            r"\b(and|then|and then) (\w+ing)\b",
            lambda m: (
                f"{m.group(1)} {_lemma_verb(m.group(2))}" if _lemma_verb(m.group(2)) in _VERB_FORMS else m.group(0)
            ),
            minded,
        )
    text = minded
    # "(would it be possible to) have the cup resting on the saucer": a causative states the wish ("get the bowl
    # sitting on the stove" is a pick of the bowl there: not "get"; and the participle is of the same clause)
    text = re.sub(
        r"(^|\bto |\byou )have "
        r"(?=(?:the|a|an) (?:(?!and\b)[\w]+ )+(?:sitting|resting|standing|lying|placed|put|set|moved)\b)",
        r"\1i want ",
        text,
    )
    # "i'd appreciate the dressing going into the basket": where it goes, said as it going there
    text = re.sub(
        r"\bi want ((?:the|a|an) [\w ]+?) (?:going|getting put|being put|ending up) "
        r"(?=(?:into|onto|in|on|inside|on top of|to) (?:the|a|an)\b)",
        r"i want \1 ",
        text,
    )
    # "what i want is the cup on the saucer" (a cleft), "i want to see the cup on the saucer": the wish itself
    text = re.sub(
        r"\bwhat (?:i|we)(?:'m|'re| am| are|'d| would)? (?:want|need|like|am after|are after|after|hoping|hope|expect"
        r"|expecting|looking for)(?: to see| to have| to get)?(?: at the end| in the end| by the end| when you're done|"
        r" afterwards)? (?:is|are)\b",
        "i want",
        text,
    )
    # a wish hedged ("i only want the ketchup in the basket", "we just need ..."): the wish itself
    text = re.sub(r"\b(i|we) (?:only|just|really|simply|actually|mainly) (want|need)\b", r"\1 \2", text)
    text = re.sub(
        r"\b(i|we) (want|need|like|love) to (?:see|have|find|get)\b(?= (?:the|a|an|both|all) )", r"\1 \2", text
    )
    # "the plate needs a scrub", "the plate could do with a wipe": the action is the noun the thing needs
    text = re.sub(
        r"^((?:the|a|an|this|that|my) [\w ]+?) (?:needs|could use|could do with|wants|requires|is due) (?:a |an )?"
        r"(?:(?:good|quick|proper|thorough|little|light) )?(scrub|wipe|clean|wash|polish|rub|going-over|going over|"
        r"once-over|once over)\b",
        r"scrub \1",
        text,
    )
    text = re.sub(
        r"\bgive ((?:the|this|that|my) [\w ]+?) an? (?:(?:good|quick|proper|thorough|little|light) )?"
        r"(?:going-over|going over|once-over|once over|rub|polish)\b",
        r"scrub \1",
        text,
    )
    # "the drawer number two (counting) from the top": the ordinal
    text = re.sub(
        r"\b(\w+) (?:number|no\.?) (one|two|three|four|1|2|3|4),? (?:counting |counted |going )?"
        r"(from the (?:top|bottom|left|right))",
        lambda m: f"{_ORDINAL_OF[m.group(2)]} {m.group(1)} {m.group(3)}",
        text,
    )
    # "down from atop the cabinet", "from on top of the cabinet": where it is taken from, said as its top
    text = re.sub(
        r"\b(?:down |up )?from (?:atop|on top of|off of|off) (?:the )?(?!top\b)", "from the top of the ", text
    )
    # "the right-hand bowl", "the higher-up one": the side or the height alone
    text = re.sub(r"\b(left|right)[- ]hand(?:ed)?(?= (?!side\b)[a-z])", r"\1", text)
    text = re.sub(r"\b(higher|lower)[- ](?:up|down)\b", r"\1", text)
    # "move the eef over the basket": the gripper carries what it holds ("... then open the gripper")
    text = re.sub(
        r"\b(move|bring|take|position|put) (?:the |your )?(?:eef|ee|end[- ]effector|gripper|hand|arm|tool)"
        r" (?=(?:over|above|to|into|onto) (?:the|a|an) (?!(?:left|right|front|back|side)\b))",
        r"\1 it ",
        text,
    )
    # "let the pear sit in the bowl": a carry to where it is let be
    text = re.sub(
        r"^let ((?:the|a|an) [a-z' ]+?) (?:sit|rest|stay|lie|stand|live) (?=(?:in|inside|on|on top of)\b)",
        r"put \1 ",
        text,
    )
    # "twist the knob so the burner comes on": until it is on
    text = re.sub(
        r"\bso(?: that)? (the [a-z' ]+?|it) (?:comes|goes|turns|switches|gets|will be|is) (on|off)\b",
        r"until \1 is \2",
        text,
    )
    # "within the tray": in it; "switch it on already": impatience, no word of what or where
    text = re.sub(r"\bwithin (?=(?:the|a|an|it|them)\b)", "in ", text)
    text = re.sub(r"\s+already(?=\s*(?:[,.!?;]|$))", "", text)
    # "that is not sitting directly on the table", "squarely on the plate": the adverb adds nothing to where
    text = re.sub(r"\b(?:directly|squarely) (?=(?:on|in|inside|on top of|onto|into) )", "", text)
    # "the middle-of-the-table black bowl": where it is, said after it
    text = re.sub(
        r"\b([a-z]+)-of-the-([a-z]+) ([a-z]+(?: [a-z]+){0,2}?)"
        r"(?=\s*(?:->|\b(?:onto|into|on|in|to|goes|go|should|please)\b|[,.;:!]|$))",
        r"\3 in the \1 of the \2",
        text,
    )
    # "the box that is neither cream cheese nor pudding": ruled out by both
    text = re.sub(
        r"\b(the|a|an|any) ([\w ]+?) (?:(?:that|which) )?(?:is|are) neither (?:the |a |an )?([\w ]+?)(?: ones?)? nor "
        r"(?:the |a |an )?([\w ]+?)(?: ones?)?(?=\s+(?:in|into|on|onto|to|inside|goes|go|should|please)\b|\s*$|,)",
        r"\1 \2 not \3 nor \4",
        text,
    )
    # "give the drawer a pull" / "a push": a drawer or a door pulled opens, pushed closes
    text = re.sub(
        r"\bgive ((?:the|this|that) [\w ]*?(?:drawer|door)) an? (?:(?:good|quick|firm|little|gentle|light) )?"
        r"(pull|tug|yank|push|shove)\b",
        lambda m: f"{'open' if m.group(2) in ('pull', 'tug', 'yank') else 'close'} {m.group(1)}",
        text,
    )
    # "yank the drawer open", "nudge the door shut": whatever the verb, the state after it says the step
    text = re.sub(
        r"^(?!(?:open|close|shut|pull|push|leave|keep|get|make|have|want)\b)[a-z]+ "
        r"((?:the|a|an) (?:(?!and |then )[a-z]+ ){0,2}(?:drawer|door|cabinet|lid|fridge|microwave|oven|cupboard)) "
        r"(open|shut|closed)\s*[.!]?$",
        lambda m: f"{'open' if m.group(2) == 'open' else 'close'} {m.group(1)}",
        text,
    )
    # "the tray: park the cube there": "there" is the place named first
    text = re.sub(
        r"^((?:the|a|an) [a-z ]+?)\s*:\s*([a-z]+) ((?:the|a|an) [a-z ]+?) (?:in |on )?there\s*[.!]?$",
        r"\2 \3 to \1",
        text,
    )
    # "give the plate a scrub": the action is the noun after the object
    text = re.sub(
        r"\bgive ((?:the|this|that|my) [\w ]+?) an? (?:(?:good|quick|proper|thorough|little|light) )?(\w+)\b",
        _give_a,
        text,
    )
    # which one of several: "the second bowl from the left", "the farther of the two", "not the blue one" (before
    # the fillers: "first" is otherwise one)
    text = re.sub(r"\s+[-\u2013\u2014]+\s+", ", ", text)  # a dash between two parts is a comma
    # "basket it", "plate the bowl": a container or a surface said as the verb puts the thing in or on it
    text = re.sub(rf"(^|[,;:] |\band |\bthen )({'|'.join(CONTAINERS)}) (it|them)\b", r"\1put \3 in the \2", text)
    # ... "could you basket the ketchup?": said of a thing, only the containers one packs things into
    text = re.sub(
        r"(^(?:(?:could|can|would|will) you |please )?|[,;:] |\band |\bthen )(basket|bin|box|crate|hamper|drawer|jar) "
        r"((?:the|a|an|that|this) [^,;:.?!]+?)(?=\s*(?:$|[,;:.!?]|\band\b|\bthen\b|\bplease\b))",
        r"\1put \3 in the \2",
        text,
    )
    text = re.sub(
        rf"(^|[,;:] |\band |\bthen )({'|'.join(_SURFACES)}) (it|them|(?:the|a|an|that|this) [^,;:.]+?)"
        r"(?=\s*(?:$|[,;:.!?]|\band\b|\bthen\b))",
        r"\1put \3 on the \2",
        text,
    )
    # "sort the blocks, red into the green tray and ...": the items of the sort, as after a colon
    text = re.sub(
        r"^((?:(?:could|can|would|will) you (?:please )?)?(?:sort|arrange|organi[sz]e|split|separate|distribute) "
        r"(?:the|these|those|both) \w+(?: up| out)?),\s+"
        r"(?=\w+(?: \w+)? (?:into|in|onto|on|to) )",
        r"\1: ",
        text,
    )
    # a label for the goal said first ("end state: ...", "goal - ..."): what follows is the goal
    text = re.sub(
        r"^(?:the )?(?:end state|final state|end result|desired state|end goal|final goal|goal state|target state|"
        r"goal|target|objective|aim|result|outcome|"
        r"(?:target|goal|final|end) (?:pose|configuration|position)|"
        # ("two drops: ...", "sorting check: ...": how many steps, or what the run checks)
        r"(?:two|three|four|2|3|4) (?:drops|moves|steps|jobs|tasks|parts|placements|transfers)|"
        r"(?:sorting|stacking|placement|grasp|drawer|stove|pour|scrub|push|lift) (?:check|test|task|job))"
        # ("end state for this one: ...", "goal this time: ...": which task it is the goal of)
        r"(?: for (?:this|the next|this next) (?:one|task|scene|trial|run|episode|ep|round|demo|take|attempt|test|"
        r"rollout|eval|go)| this time| here)?"
        # ("final state i'd like: ...", "end result we want: ...": the label and whose wish it is)
        r"(?: (?:i|we)(?:'d| would)? (?:like|want|need|am after|are after|'m after|'re after))?\s*[:,]\s*",
        "",
        text,
    )
    # the place said as the goal's pose ("...; target pose is inside the basket"): where the thing goes
    text = re.sub(
        r"(^|[;,.] )(?:the )?(?:target|goal|final|end) (?:pose|position|location|spot|place)(?: for it)? "
        r"(?:is|should be|will be)\s+(?=(?:in|inside|on|onto|on top of|into)\b)",
        r"\1it goes ",
        text,
    )
    # ... or said to be the goal ("end state should be the bowl ... resting on the plate")
    text = re.sub(
        r"^(?:the |my |our |your )?(?:end state|final state|end result|desired state|end goal|final goal|goal state|"
        r"target state)\s+(?:(?:should|must|will|would|needs? to|has to|is going to) be|is)\s+(?=(?:the|a|an) )",
        "",
        text,
    )
    # a sentence adverb said first ("ideally the cup ...", "hopefully ..."): a comment on the goal, not a word of it
    text = re.sub(r"^(\w+ly)\b,?\s*", lambda m: "" if adverb_only(m.group(1)) else m.group(0), text)
    # "right next to", "just by": the adverb adds nothing to the relation (and "right" is no side here)
    text = re.sub(
        r"\b(?:right|just|directly|immediately) (?=(?:next to|beside|by|near|behind|in front of|under)\b)", "", text
    )
    # "the cupboard's sliding compartment": a cabinet's compartment that slides out is its drawer
    if re.search(r"\b(?:cabinet|cupboard|dresser|chest)\b", text):
        text = re.sub(r"\b(?:sliding |pull-out |pullout )?compartment(s?)\b", r"drawer\1", text)
    # "(nothing else moved)", "- nothing else changes": what stays as it is, no step
    text = re.sub(
        # (a sentence of its own takes the stop before it: "the drawer open. nothing else changes.")
        r"(?:[,;-]|(?<=\w)[.!])?\s*\(?\s*(?:and )?nothing else (?:moved|moves|changes|changed|touched|is touched|"
        r"is moved|should change|should move)\s*\)?(?=\s*[.!]?$)",
        "",
        text,
    )
    # "... result: three-block tower": what the steps before make, said again
    text = re.sub(
        r"[.;,]\s*(?:result|outcome|end result)\s*:\s*(?:a |one )?(?:[\w-]+ )?(?:tower|stack|pile)\s*\.?$", ".", text
    )
    # "lift it clear", "raise it clear of the table": lifted
    text = re.sub(
        r"\b(lift|raise) (it|them|the [\w ]+?) clear\b(?: of (?:the )?(?:table|counter|surface))?", r"\1 \2", text
    )
    # "the plate should carry the black bowl ...": the bowl goes on the plate
    text = re.sub(
        r"^(?:the )?(\w+(?: \w+)?) (?:should|must|needs to|has to) (?:carry|hold|support) ((?:the|a|an) [^.!?,]+?)"
        r"\s*[.!?]?$",
        r"put \2 to the \1",
        text,
    )
    # "into the very same mug": the mug ("pour the beads from the mug into the very same mug" stays nonsense)
    text = re.sub(r"\b(into|onto|in|on|to|inside) the (?:very )?same (?=\w)", r"\1 the ", text)
    # "get the drawer open", "get it shut": open or close it
    text = re.sub(
        r"\bget(?:ting)? ((?:the|that|this) [\w ]*?drawer|it) (open|opened|shut|closed)\b",
        lambda m: f"{'open' if m.group(2).startswith('open') else 'close'} {m.group(1)}",
        text,
    )
    # "slide the drawer back into the cabinet": closed
    text = re.sub(
        r"\b(?:slide|push|shove|ease) ((?:the|that) [\w ]*?drawer) back (?:into|in to|inside) (?:the|its) "
        r"[\w ]*?(?:cabinet|cupboard|dresser|chest|unit)\b",
        r"close \1",
        text,
    )
    # "twist the stove's knob to get it going": the stove turned on
    text = re.sub(
        r"\b(?:twist|turn|rotate|crank) (?:the )?([\w ]+?)(?:'s)? (?:knob|dial) (?:to |so as to |in order to )?"
        r"(?:get (?:it|them) (?:going|started|running|on|lit|heating)|start (?:it|them)(?: up)?|fire (?:it|them) up|"
        r"light (?:it|them)|switch (?:it|them) on|turn (?:it|them) on)\b",
        r"turn on the \1",
        text,
    )
    # "tuck the red block away inside", "... stash it in there": inside the thing named before
    text = re.sub(r"\baway inside(?=\s*[.!?]?$)", "inside it", text)
    # "the cabinet beyond the red block", "in back of the bowl": behind it
    text = re.sub(r"\b(?:beyond|in back of)(?= (?:the|a|an|that|this) )", "behind", text)
    # "in the gap between the plate and the ramekin": between them
    text = re.sub(r"\b(?:in|at|on) the (?:gap|space|spot|area|middle) between\b", "between", text)
    # a cleft: "it is the upper bowl i want on the plate" is the wish "i want the upper bowl on the plate"
    text = re.sub(r"^it is ((?:the|a|an) .+?) (?:that )?(i|we) (want|need)\b", r"\2 \3 \1", text)
    # the base of a stack said to stay ("the blue block stays at the bottom: green goes on it ..."): the thing is
    # named for what follows, and nothing is done to it
    text = re.sub(
        r"^((?:the |a |an )?[\w ]+?) (?:stays|remains|sits|stands|should stay|can stay|will stay|is staying) "
        r"(?:put|at the bottom|on the bottom|where it is|in place|as is|as the base|at the base)\s*[:;,.-]\s*(?=\w)",
        r"there is \1 . ",
        text,
    )
    # where a thing to use is, said after the request ("plate clean, sponge is right there"): the thing is named
    # (it must be in the scene) before the request
    text = re.sub(
        r"^(.+?),\s*(?:and )?(?:the |a |your )?([a-z]+(?: [a-z]+)?) (?:is|are) (?:right |just |over )?(?:there|here|"
        r"nearby|close by|to hand|handy|next to it|beside it|by it)$",
        r"there is the \2 . \1",
        text,
    )
    text = _named_after(text)
    for which, said_plainly in _WHICH_PLAINLY:
        text = re.sub(which, said_plainly, text)
    text = _SAME_AGAIN.sub(lambda m: _same_again(m, text), text)
    text = qualify(text)
    # "the beads that are (sitting) in the red mug": what a container holds, said by where it is (a relative clause
    # after a destination stays: "on the plate that's on the stove" says which plate, not a second destination)
    text = re.sub(
        rf"\b((?:the|some|all the) (?:{'|'.join(CONTENTS)})) (?:that|which) (?:is|are) "
        r"(?:(?:sitting|resting|lying|kept) )?(?=(?:in|inside) (?:the|a|an|your) )",
        r"\1 ",
        text,
    )
    # "pick up the juice instead of the ketchup and put it ...": the thing set apart mid-sentence is named, no step
    text = re.sub(
        r"^(.*?\S) (?:instead of|rather than) ((?:the|that|this) [\w' ]+?)(?= and | then |,\s*(?:and |then )?\w)",
        r"there is \2 . \1",
        text,
    )
    # "put the bowl on the plate and not on the stove": the place set apart, as after a comma (discourse._contrast)
    text = re.sub(
        r" and not (?=(?:on|in|into|onto|inside|on top of|next to|beside|by|near|under) (?:the|a|an) )", ", not ", text
    )
    # "leave the bbq sauce and the salad dressing alone": each is left alone
    text = re.sub(_TWO_LEFT_ALONE, r"\1 \2 \4 and \1 \3 \4", text)
    text = re.sub(_LEAVE_ALONE, _left_be, text)
    # "not the one on the stove: the other black bowl, ...": the thing set apart is a sentence of its own
    text = re.sub(r"(^|[.;!?] )(there is [^:;.!?]+?)\s*:\s*(?=\w)", r"\1\2 . ", text)
    # "one of the black bowls is on the stove": that one, the bowl on the stove, named for what follows
    text = re.sub(
        r"(^|[.;!?] )one of the ((?:\w+ ){0,2})(\w+s) (?:is|sits|rests|stands)(?: sitting| resting| standing| lying)? "
        r"(?:up |down |over |now )?"
        r"((?:on top of|on|in|inside|next to|beside|near|by) (?:the|a|an) [\w ]+?)"
        # (or a comma before the step that acts on it: "..., bring it down and set it on the plate"; "- that one,
        # put it ...")
        r"(\s*(?:,|\s-+|:)\s*(?:(?:that|this) one\s*[,:-]?\s*)?"
        r"(?=(?:and |then )*(?:bring|take|grab|pick|move|put|place|set|get|lift|carry)\b)|(?=\s*(?:[.;!?]|$)))",
        lambda m: (
            f"{m.group(1)}there is the {m.group(2)}{singular(m.group(3))} {m.group(4)}"
            + (". " if m.group(5).strip() else "")
        ),
        text,
    )
    for said, plainly in _SAID_PLAINLY:
        text = re.sub(said, plainly, text)
    if starts_with_verb(text):  # "push the red block forward, into the green area": where it goes, after a comma
        text = re.sub(
            r"(?<=[a-z]),\s*(?=(?:straight |right |directly )?(?:into|onto|on top of) (?:the|a|an) )", " ", text
        )
    text = _thing_then_place(text)
    # "top drawer open with the cream cheese inside": the drawer opened, then the thing put in it
    text = re.sub(
        r"^(?:(?:i want|i need|i would like|we want|we need) )?(?:the )?"
        r"((?:[a-z]+ ){0,2}(?:drawer|cabinet|box|cupboard|microwave|fridge)(?: of the [a-z ]+?)?) "
        r"(?:(?:should|must|needs? to|has to) be |is |to be )?(?:open|opened|pulled out),? "
        r"with ((?:the|a|an) [a-z ]+?) (?:(?:sitting|resting|lying|placed|put|stowed|tucked) )?"
        r"(?:inside|in it|inside it|in there|in)\s*[.!]?$",
        r"open the \1 and put \2 inside",
        text,
    )
    # "open the drawer, then red block in, that's it": a thing and only "in" after a step, put in what it worked
    text = re.sub(
        r"(\bthen |, )((?:the |a )?[a-z]+(?: [a-z]+)?) (?:in|inside|in there)(?=\s*(?:[,.;!]|$))",
        lambda m: m.group(0) if _verb_first(m.group(2)) else f"{m.group(1)}put {m.group(2)} in it",
        text,
    )
    # "the bbq sauce into the basket, not the tomato sauce": the thing ruled out is named, and not moved
    text = re.sub(r",\s*(?:and |but )?not (the|that|this) ([\w' ]+?)(?=\s*(?:[.;!?]|$))", r" ; there is \1 \2", text)
    text = re.sub(r",\s*(?=(?:which|who) (?:is|are)\b)", " ", text)  # "the block, which is on the plate," locates it
    text = re.sub(r"[!?;]+|\.(?=\s|$)", " . ", text)
    text = text.replace("next to", "next_to")  # a relation, not the filler "next"
    for f in sorted(FILLERS, key=len, reverse=True):
        text = re.sub(rf"(^|\s|,|\.){re.escape(f)}(?=\s|,|\.|$)", r"\1 ", text)
    text = text.replace("next_to", "next to")
    text = re.sub(r"\s+", " ", text)
    out = [s.strip(" ,") for s in text.split(" . ") if s.strip(" ,.")]
    # a sentence that only links to the one before ("...; after that the red block goes on ..."), and one that
    # only closes the request ("that is it", "done", "nothing else")
    out = [
        re.sub(r"^(?:and )?(?:then|after that|afterwards|after which|once that is done|next)\s*,?\s+", "", s)
        for s in out
    ]
    # "once it is there, put ...": a step done before, said again only to link the next to it
    out = [re.sub(_DONE_BEFORE_AFTER_STEP, r"\1", re.sub(_DONE_BEFORE, "", s)) for s in out]
    return [s for s in out if not _CLOSING.fullmatch(s)]


_DONE = (
    r"(?:once|when|after|as soon as) (?:it|that|this|they|those|both) (?:is|are|has been|have been) "
    r"(?:there|done|in place|placed|down|finished|on it|in it|in there|on there|settled|open|opened|closed|shut|on|"
    r"off)\s*,?\s+(?:then\s+)?"
)
_DONE_BEFORE = re.compile(rf"^(?:and )?{_DONE}")
# "pull the drawer open, and once it's open put the block inside": the same link after a step in one sentence
_DONE_BEFORE_AFTER_STEP = re.compile(rf"(,\s*(?:and )?|\band ){_DONE}")


# Wordings said plainly, in order (sentences()): a goal said as the thing in the state wanted ("a table with no dirt
# left on it"), dirt got off a thing (a wipe), a wish closed by how good it would be, "take hold of" (grab),
# "straight onto" (onto), the order said again ("not the other way round"), a pour said by its manner ("get them
# into the bowl by pouring").
# What a speaker says around the request that is no part of it: a close ("... ok that's all", "uh yeah thats it",
# "..., then you can stop there"), when it is wanted ("when you're done, ..."), and an aside about where the thing
# already is ("take the closer one, it's sitting on the ramekin, and ..."); "currently" in where a thing is.
_SPOKEN_PLAINLY: tuple[tuple[str, str], ...] = (
    (
        r"(?:[,.;!:-]\s*|\s+)(?:(?:ok|okay|uh|um|erm|yeah|yep|yes|right|alright|so|and)[,.]?\s+)*"
        r"(?:that is|thats|that|this is) (?:it|all|everything)\b"
        r"(?:[,.;!]?\s*(?:nothing else|that is all|thanks?|thank you|cheers|for now|done))*\s*[.!]*$",
        "",
    ),
    (r"(?:,\s*|\s+)(?:and )?(?:then )?you can stop(?: there| after that| then| now| here)?\s*[.!]*$", ""),
    # "... - that's the whole job this time", "... - nothing else needs to move", "... - just that bottle"
    (
        r"[,.;!:-]\s*(?:(?:and|but|so|ok|okay)\s+)?(?:(?:that is|thats|that|this is|that will be) (?:the whole "
        r"(?:job|task|thing|point)|the (?:finish line|goal|plan|idea|job|task|wish|aim|end of it)|all (?:i am|we are) "
        r"after|what i (?:want|need|am after))|nothing else (?:needs to|has to|should|will|is to)? ?(?:move|change|be "
        r"touched|be moved|needs touching|matters)|(?:just|only) (?:that|this)(?: one| bottle| thing| item| box)?)"
        r"(?: this time| today| here| for now| this round)?\s*[.!]*$",
        "",
    ),
    # "take it out and stack it on ...": out from where it is, which the pick says already (a drawer pulled out is
    # opened, so only takes)
    (r"\b(take|get|lift) (it|them) out\b(?! of)", r"\1 \2"),
    (r"^(?:when|once|after) (?:you are|you have) (?:done|finished|through)(?: with (?:that|this|it))?,?\s*", ""),
    (
        r",\s*(?:it is|that is|which is) (?:sitting |resting |standing |lying |located |placed )?"
        r"(?:on|in|inside|next to|by|beside|near|on top of) (?:the|a|an) [a-z ]+?,\s*(?=and\b|then\b)",
        ", ",
    ),
    (
        r"\b((?:that|which) (?:is|are)) (?:currently|presently|now|still|right now) "
        r"(?=(?:(?:sitting|resting|standing|lying|perched|located|placed|kept|parked) )?"
        r"(?:on|in|inside|next to|by|beside|near)\b)",
        r"\1 ",
    ),
    # "the red block should end up inside the green square, push it in there": the goal, then how to get it there
    (
        r"^((?:the |a |an )?[a-z ]+?) (?:should|must|needs? to|has to|is to) (?:end up|go|be|sit) "
        r"((?:in|inside|into|on|onto|on top of|in front of|next to|at) [a-z ]+?),?\s*"
        r"(push|slide|shove|nudge) it(?: (?:in|over|on|up))? "
        r"(?:there|in there|over there)\s*[.!]?$",
        r"\3 \1 \2",
    ),
    (r"^((?:push|slide|shove|nudge) [a-z ]+?) (?:inside|in) (?=(?:the|a|an) )", r"\1 into "),
    # "get the red block into the green square by pushing it forward": the means is the verb
    (
        r"^(?:get|move|bring|put) ((?:the|a|an) [a-z ]+?) (into|onto|in|to|in front of|to the front of) ([a-z ]+?),? "
        r"by (?:pushing|sliding|shoving|nudging) (?:it|them)( forward| forwards| back| left| right)?\s*[.!]?$",
        r"push \1\4 \2 \3",
    ),
    (r"\b(?:marked|drawn|painted|printed|taped|outlined) on the (?:table|tabletop|floor|counter)\b", ""),
    # "turn the stove's knob to switch the stove on": the knob's purpose says which way
    (
        r"^(?:turn|twist|rotate) ((?:the|its) [a-z' ]+?) to (?:switch|turn) (?:the [a-z ]+?|it) (on|off)\s*[.!]?$",
        r"turn \2 \1",
    ),
    # "the item closest to you is the bbq sauce. pick that one up ...": the thing named, for what follows
    (
        r"^(?:the )?[a-z ]*?\b(?:item|thing|object|one|product|bottle|box|jar|can|carton|tin|packet|package|container)"
        r"\b[a-z ]*? is ((?:the|a|an) [a-z ]+?)\s*(?=[.;:]|,\s*(?:pick|grab|take|get|put|move|lift)\b|$)",
        r"there is \1",
    ),
    # what is not meant, between two steps ("grab the bowl in the drawer, not the one on the cabinet, and set it ...")
    (r",\s*not (?:the|that|this) (?:one|ones?|[a-z]+)(?: [a-z]+){0,6}?,\s*(?=(?:and|then)\b)", ", "),
    # "the table should end up clean, with none of the brown dirt left on it": the cleaning goal said again
    (
        r",\s*with (?:no|none of (?:the|those|these|that|any)) (?:[a-z]+ ){0,2}"
        rf"{DIRT} (?:left|remaining)"
        r"(?: on it| on the [a-z]+)?\s*[.!]?$",
        "",
    ),
)


# Words before "one" that say which of several, not what it looks like.
_NOT_A_LOOK = frozenset(
    ["other", "same", "next", "last", "first", "second", "third", "only", "right", "left", "correct"]
)


def _apposed_look(text: str) -> str:
    """What a thing looks like, said after it as "the <word> one" ("the farther block, the red one", "the smaller of
    the two cubes (the red one)", "the peg on the left, the square one"): the word before its noun."""

    def merged(m: re.Match) -> str:
        before, noun, look = m.group(1), m.group(2), m.group(3)
        if look in _NOT_A_LOOK or re.search(r"\bones?\b", before) or not is_thing(noun):
            return m.group(0)  # "the one on the shelf, the other one": which one, not what it looks like
        return f"the {before}{look} {noun} "

    text = re.sub(
        r"\bthe ([a-z]+)( (?:on|to|at) the (?:left|right|front|back)(?: side)?)\s*,\s*the ([a-z]+) one\b",
        lambda m: f"the {m.group(3)} {m.group(1)}{m.group(2)}" if is_thing(m.group(1)) else m.group(0),
        text,
    )
    text = re.sub(
        r"\bthe ((?:[a-z]+ ){0,4}?)([a-z]+)\s*(?:,\s*|\(\s*)the ([a-z]+) one\s*(?:\)\s*|,\s*|$)", merged, text
    )
    return text.strip()


# What is said after the request about the thing, or how it is held, in the words the readers know.
_HOW_PLAINLY: tuple[tuple[str, str], ...] = (
    # what the thing looks like, said after the request about it ("...; it's the flat box"): no step
    (r"(?<=\S)\s*[;.]\s*(?:it is|it's|its) (?:the|a|an) (?:[a-z]+ ){0,2}[a-z]+\s*[.!]?$", ""),
    # "pot lifted off the table, held with both arms by its two handles": how it is held, said after the goal
    (r"^(?=[a-z]+ (?:lifted|raised|held up|picked up|up off|up from)\b)", "the "),
    (
        r",\s*(?:and )?held (?:up )?(?:(?:with|by|in|at|from) (?:both|two|the two|its two|its|the) (?:its )?"
        r"(?:arms|hands|grippers|handles)\s*){1,2}[.!]?$",
        ", holding it by its two handles with both arms",
    ),
)
# Which thing, said in words the qualifier reader knows (before it runs).
# "..., then do the same with the blue block (and the yellow tray)", "do likewise for the bowl": the step before,
# said again of another thing (and another place)
_SAME_AGAIN = re.compile(
    r"(?:do|repeat) (?:the same(?: thing)?|likewise|that|this|it)(?: again)? (?:with|for|to|using) "
    r"((?:the|that|this) [\w ]+?)"
    r"(?:,?\s+(and|with|into|in|onto|on|to|for)\s+((?:the|that|this) [\w ]+?))?(?=\s*(?:[,;.!?]|$))"
)
_PLACE_WORD = re.compile(r"\b(into|inside|in|onto|on top of|on)\s+(?:the|a|an)\s")


def _same_again(m: re.Match, text: str) -> str:
    """The step before `m`, said again of the thing `m` names (and the place it names): "put the blue block in the
    yellow tray" for "do the same with the blue block and the yellow tray" after a carry into a tray; with two things
    of one kind ("... with the blue block and the green block"), once for each. Unchanged when no step before says
    what to do."""
    thing, joiner, place = m.group(1), m.group(2), m.group(3)
    before = text[: m.start()]
    if joiner == "and" and place and _head(place) == _head(thing):
        steps = [_again(before, t, None) for t in (thing, place)]
        return ", ".join(x for x in steps if x) if all(steps) else m.group(0)
    return _again(before, thing, place) or m.group(0)


def _again(before: str, thing: str, place: str | None) -> str | None:
    """The last step said in `before`, done to `thing` (and carried to `place`); None when there is none."""
    parts = re.split(r"[,;.]\s*|\s+then\s+|\s+and\s+(?=(?:then\s+)?\w+ (?:it|them|the|a|an)\b)", before)
    step = next((b.strip() for b in reversed(parts) if starts_with_verb(b.strip())), None)
    if step is None:
        return None
    if place:
        rel = [p.group(1) for p in _PLACE_WORD.finditer(before)]
        into = not rel or rel[-1] in ("into", "inside", "in")
        return f"put {thing} {'in' if into else 'on'} {place}"
    again = re.sub(
        r"^(\w+(?: up| down| out)?) (?:(?:the|a|an|that|this) [\w ]+?|it|them)"
        r"(?= (?:in|into|inside|on|onto|to|from|off|and|on top of)\b|$)",
        lambda s: f"{s.group(1)} {thing}",
        step,
        count=1,
    )
    return again if again != step else None


_WHICH_PLAINLY: tuple[tuple[str, str | Callable[[re.Match], str]], ...] = (
    # "the cube at the bottom of the stack", "the cube that's underneath the green one": where it is in a stack
    (r"\b(\w+) (?:that is |which is )?at the (bottom|top) of the (?:stack|pile|tower)\b", r"\2 \1"),
    (r"\b(?:underneath|beneath|below)\b(?= (?:the|a|an|it|that|this)\b)", "under"),
    # "anything but the bowl in the middle - put the other black bowl ...": the one left alone, said first
    (r"^(?:anything|everything|any|all) but (the [\w' ]+?)\s*(?=[-,:;] )", r"leave \1 alone"),
    # "except for the bowl on the cookie box there's one more black bowl, put that one ...": the other one
    (
        r"^(?:except(?: for)?|apart from|besides|other than|aside from) (the [\w' ]+?),? there is (?:one more|another|"
        r"one other|also (?:a|another)|a second) ([\w' ]+?)\s*[,;.:-]\s*(\w+(?: up)?) (?:that one|that|it)\b",
        r"leave \1 alone, \3 the other \2",
    ),
    # "the bowl sitting on the table? no, not that one, the other black bowl. put it on the plate": corrected
    (
        r"^(the [\w' ]+?)\s*\?\s*no\b[,.!]?\s*(?:not (?:that one|that|it)[,.!]?\s*)?(the other [\w' ]+?)\s*[,;.:-]\s*"
        r"(\w+(?: up)?) (?:it|that one|that)\b",
        r"leave \1 alone, \3 \2",
    ),
    # "the plate gets a black bowl: the one that is not on the cabinet": which one, said after the kind
    (
        r"\b(?:a|an|one) ((?:\w+ ){0,2}\w+)\s*(?::|,|-+)\s*the one (?:that |which )?(?:is |sits |stands )?"
        r"(?=(?:not|on|in|inside|next to|near|by|beside|under|on top of|closest|nearest|farthest|furthest)\b[^,;.:]*$)",
        r"the \1 that is ",
    ),
    # "put a black bowl on the plate: the one on the stove": which one, said after the request
    (
        r"^((?:\w+ )+?)(?:a|an) ((?:\w+ ){0,2}?\w+) ((?:on|in|into|onto|inside|on top of) (?:the|a|an) [\w ]+?)"
        r"\s*(?::|,|-+)\s*the one (?:that is |which is |sitting |that sits )?"
        r"((?:not )?(?:on|in|inside|next to|near|by|beside|under|on top of|closest to|nearest to) (?:the|a|an) "
        r"[^,;.:!?]+?)\s*[.!]?$",
        r"\1the \2 \4 \3",
    ),
    # "then do the same with the blue block, but that one goes in the yellow tray": a carry of its own
    (
        r"\bdo the same (?:with|for|to) ((?:the|that|this) [\w ]+?),? (?:but|only|except|though) "
        r"(?:that one|this one|that|it|this) (?:goes|should go|belongs|needs to go|has to go|must go|is to go) "
        r"(in|into|on|onto|inside|on top of) ",
        r"put \1 \2 ",
    ),
    # "the one sitting lower", "the bowl placed higher": the lower one
    (
        r"\bthe (one|\w+) (?:that is |which is )?(?:sitting|placed|resting|standing|lying|set|located) "
        r"(lower|higher|further|farther|closer|nearer)(?: down| up)?\b",
        r"the \2 \1",
    ),
    # "the grey stove sitting on the table in front of you": the table in front of the robot is where everything
    # stands (without "in front of you" it stays: "the cube sitting on the table" is the bottom one of a stack)
    (
        r"\s*\b(?:that is |which is )?(?:sitting|standing|lying|resting|placed) on the (?:table|counter|tabletop)"
        r" (?:right )?in front of (?:you|me|the robot)(?=\s*(?:[,;.!?]|$))",
        "",
    ),
    # "the cube that's not on top (at the moment)": of a stack of two, the bottom one (and the other way round)
    (
        r"\b(\w+) (?:that is |which is )?not (?:on top|at the top|on the top|(at|on) the bottom)"
        r"(?! of (?!the (?:stack|pile|tower)\b))(?: of the (?:stack|pile|tower))?"
        r"(?: (?:at the moment|right now|currently|now))?\b",
        lambda m: f"{'top' if m.group(2) else 'bottom'} {m.group(1)}",
    ),
    # "there are two black bowls - put the closer one on the plate": which of them, said as "of the two ..."
    (
        r"^there(?: are|'re| re) (two|three|2|3) ([a-z ]+?s)\s*[,;:.!]\s*"
        r"(?=(?:put|place|set|move|take|grab|pick|stack|lift|bring|drop|get)\b)",
        r"of the \1 \2, ",
    ),
)
_SAID_PLAINLY: tuple[tuple[str, str], ...] = (
    # "the drawer at the top": the top drawer (not "at the top of the cabinet", a place)
    (r"\bthe ([a-z]+) at the (top|bottom|middle)\b(?! of\b)", r"the \2 \1"),
    # "up on the cabinet with it", "into the bowl with them": the thing carried, said again after its place
    (r"\b((?:into|onto|in|on|on top of|inside) (?:the|a|an) [\w ]+?) with (?:it|them)\b", r"\1"),
    # "give the red block a push forward", "give the plate a good scrub": the noun is the verb
    (
        r"\bgive ((?:the|a|an|that|this) [\w ]+?) (?:a|one) (?:good |quick |little |small |gentle |firm |light )?"
        r"(push|nudge|shove|scrub|wipe|clean|rub|polish)\b,?",
        r"\2 \1",
    ),
    # "pour what's in it into the bowl": what a container holds, said as its contents
    (r"\bwhat(?:'s| is) (?:in|inside) it\b", "its contents"),
    (
        r"\bwhat(?:'s| is) (?:in|inside) ((?:the|that|this) [\w ]+?)(?= (?:into|in|onto|on|over|to)\b)",
        r"the contents of \1",
    ),
    # "get the beads out of the mug and into the bowl": a source and a destination in one breath
    (r"\bout of ((?:the|a|an) [\w ]+?),? and (into|in|onto|on|to|over) (?=(?:the|a|an) )", r"from \1 \2 "),
    # "not the ketchup, the milk. that's what goes in the basket": the thing just named, where it goes
    (
        r"([.;!?] )(?:that|this)(?: one)? (?:is (?:what|the one(?: that| which)?) )?(?:goes|belongs|should go|"
        r"needs to go|has to go|must go) (?=(?:in|into|on|onto|inside|on top of|to) )",
        r"\1put it ",
    ),
    # "whatever is closest to you, put that in the basket": the one that is so, acted on
    (
        r"(^|[.;!?] )(?:whatever|whichever(?: one| thing| item)?) (?:is|sits|stands) ([\w ]+?),? "
        r"(?:(?:just|then|go ahead and) )?(\w+) (?:that|it)\b",
        r"\1\3 the thing that is \2",
    ),
    # "open up the drawer": the particle adds nothing
    (r"\bopen up (?=(?:the|a|an|that|this) )", "open "),
    # "the ramekin has a bowl next to it - put that bowl ...": the thing named by where it is, then acted on
    (
        r"(^|[.;!?] )(the [\w ]+?) (?:has|had) (?:a|an|one|some) ([\w ]+?) "
        r"(next to|beside|near|by|behind|in front of|on top of|on|in|inside|under) (?:it|them)\b",
        r"\1there is the \3 \4 \2",
    ),
    (
        rf"\b(?:a|the) (table|counter|surface) with no {DIRT}(?: left)?(?: on it)?\b",
        r"the \1 clean",
    ),
    # "i'd rather have the bottle on the cabinet than on the rack": the goal, and the place it is not
    (
        r"\b(?:i|we) would rather (?:have|see|keep|put) (.+?) than (?=(?:on|in|at|inside|on top of|in front of) )",
        r"put \1, not ",
    ),
    # "i want a spotless table": the table clean
    (
        r"\b(?:i|we) (?:want|would like|need) (?:a|the) (?:spotless|clean|cleaned|tidy|dirt free|dirt-free) "
        r"(table|counter|surface)(?: ?top)?\b",
        r"the \1 clean",
    ),
    # "..., all that brown dirt wiped away": the cleaning goal said again after it
    (
        r",\s*(?:and |with )?(?:all |any )?(?:of )?(?:that |the |this )?(?:\w+ )?"
        rf"{DIRT} "
        r"(?:wiped|gone|cleaned|removed|cleared|scrubbed)(?: away| off| up| out)?(?=\s*(?:[.;!?]|$))",
        "",
    ),
    # "the table top free of all that dirt": clean
    (
        r"(?:\b(?:a|the) |^)(table|counter|surface)(?: ?top)? (?:free|clear|clean|rid) of (?:all |any )?"
        rf"(?:the |that |this )?{DIRT}\b",
        r"the \1 clean",
    ),
    (
        rf"\b(?:get|take|remove|clear) (?:the |all the |any )?({DIRT}) "
        r"(?:off|from) (?:of )?((?:the|a|an) \w+(?: \w+)?)(?:'s (?:surface|top)| (?:surface|top))?\b",
        r"wipe the \1 off \2",
    ),
    (
        r",?\s+(?:would|will|'d) be (?:great|nice|lovely|good|perfect|ideal|appreciated|awesome|fantastic|brilliant)\b",
        "",
    ),
    (r"\b(?:take|get|grab|catch) (?:a )?hold of\b", "grab"),
    # "bring it down and set it on the plate": taken down from where it is, then carried
    (r"\b(?:bring|get|lift) (it|them|that one) down\b(?= and\b| then\b|\s*,)", r"take \1 down"),
    # "pass the hammer from one gripper to the other": a handover
    (
        r"\b(?:pass|hand|move|transfer|switch|shift) ((?:the|that|this) [\w ]+?|it) from one (?:arm|gripper|hand) to "
        r"the other(?: (?:one|arm|gripper|hand))?\b",
        r"pick up \1 with one arm and hand it over to the other arm",
    ),
    (r"\b(wipe|mop|clean|scrub|sponge) up (?=the|that|this|all|any)\b", r"\1 "),  # "wipe up the dirt": wipe it
    (r"\b(?:straight|directly|right) (?=(?:onto|into|on top of|on|in|inside)\b)", ""),
    (r",?\s*(?:and |but )?not (?:the other way|vice versa)(?: a?round)?(?=\s*(?:[.;!?,]|$))", ""),
    (
        r"\b(?:get|put|move|transfer|empty|send) ((?:the |them|it)[\w ]*?) (?:into|in|onto|on) ([\w ]+?),? by "
        r"(?:pouring|tipping|tilting)(?: (?:it|them))?(?: out)?\b",
        r"pour \1 into \2",
    ),
)


def _thing_then_place(text: str) -> str:
    """A thing, then after a comma only where it goes ("black bowl beside the plate, straight onto the plate"): a
    carry of that thing there. A part that starts with a verb is a step of its own, and "on"/"in" may only say where
    the thing is, so only the words that say where it goes count."""
    m = re.fullmatch(
        r"((?:the |a |an )?[a-z][a-z' ]*?),\s*(?:straight |right |directly )?((?:onto|into|on top of) (?:the|a|an) "
        r"[a-z ]+?)\s*[.!]?",
        text,
    )
    if not m or _verb_first(m.group(1)) or m.group(1).split()[0] in ("then", "and", "there", "it", "i", "we"):
        return text
    return f"put {m.group(1)} {m.group(2)}"


# A thing said by a word that names anything ("the item closest to you"), then named ("..., that's the milk").
_ANY_THING = r"(?:item|thing|object|one|product)"


def _named_after(text: str) -> str:
    """A thing said first by a word that names anything and then by its name: the name stands for it ("put the
    item closest to you in the basket, that's the milk" -> "put the milk in the basket"; "the item furthest to the
    right, the tomato sauce: put it in the basket" -> "the tomato sauce: put it ...")."""
    m = re.fullmatch(
        rf"(.*?)\bthe ([a-z ]*?\b{_ANY_THING}\b[a-z ]*?) ((?:in|into|on|onto|inside|on top of) .+?),?\s*"
        r"(?:that is|thats|that|which is|i mean|i\.e\.?|ie|namely|meaning) ((?:the|a|an) [a-z ]+?)\s*[.!]?",
        text,
    )
    if m:
        return f"{m.group(1)}{m.group(4)} {m.group(3)}"
    text = re.sub(rf"^the [a-z ]*?\b{_ANY_THING}\b[a-z ]*?,\s*(?=(?:the|a|an) [a-z ]+?\s*[,:;]\s*\w)", "", text)
    # "pick the flattest item, the butter, and place it ...": the name between commas stands for the description
    return re.sub(rf"\bthe [a-z]+ {_ANY_THING},\s*((?:the|a|an) [a-z ]+?),", r"\1", text)


def _verb_first(phrase: str) -> bool:
    """The phrase starts with a verb: one of the planner's ("fire the cooker" of "fire ... up"), or a word the
    lexicon knows only as a verb."""
    from lemminflect import getAllLemmas

    first = phrase.split()[0]
    lemmas = getAllLemmas(first)
    return first in _FIRST_WORDS or (bool(lemmas) and not {"NOUN", "ADJ", "PROPN"} & set(lemmas))


def _part_purpose(m: re.Match) -> str:
    part, verb, thing, particle = m.group(1), m.group(2).strip(), m.group(3), (m.group(4) or "").strip()
    what = part if thing in (None, "it", "them") else thing
    if verb in ("turn", "switch"):
        return f"turn {particle} {what}" if particle in ("on", "off") else m.group(0)
    return f"{verb} {what}"


# A thing to be left alone, said as a part of its own ("leave the basket where it is and drop the block into it",
# "don't touch the cream cheese - just put the butter ...", "ignore the bbq sauce; ..."): no step, but the thing is
# named, so it must be in the scene (mentions.py) and a pronoun after it may point back to it.
_LEAVE_ALONE = re.compile(
    r"(^|[,;:.?!] |- |\band |\bbut )(?:just |please )?"
    r"(leave|ignore|skip|do not touch|do not move|do not disturb|do not bother with|do not mess with|never mind|"
    r"do not (?:take|grab|use|pick up|pick|lift|get)|(?<![\w,;:.?!-] )not|"
    r"no need to (?:move|touch)|(?:you )?do not need to (?:move|touch)|"
    r"forget(?: about)?|keep away from|stay away from|avoid) "
    # (not the rest: "... and leave the rest where they are" only closes the request, _TRAILING)
    r"((?:the|that|this|those|these) (?!(?:rest|others?|other ones?|remaining ones?)\b)[\w' ]+?)"
    r"( (?:alone|where it is|where they are|as it is|as they are|as is|in place|untouched|be|where it stands|"
    r"where it sits|in peace|completely|entirely|totally|for now))?"
    r"(?=\s*(?:[,;:.!?]|- |$| and\b| but\b| then\b| just\b))"
)
_TWO_LEFT_ALONE = re.compile(
    r"\b(leave|ignore|do not touch|do not move|skip) ((?:the|that|this) [\w' ]+?) and ((?:the|that|this) [\w' ]+?) "
    r"(alone|be|untouched|where they are|as they are|in place)\b"
)
# Where "leave" puts a thing or the state it leaves it in ("leave the bowl on the plate", "leave the drawer open"):
# a step, not a thing left alone.
_LEFT_SOMEWHERE = re.compile(
    r"\b(?:on|in|into|onto|inside|on top of|under|next to|beside|by|near|at|behind|in front of)\b|"
    r"\b(?:open|opened|closed|shut|on|off|running|empty|full)$"
)


def _left_be(m: re.Match) -> str:
    lead, verb, thing, stays = m.group(1), m.group(2), m.group(3), m.group(4)
    if verb == "leave" and not stays and _LEFT_SOMEWHERE.search(thing):
        return m.group(0)
    if lead.strip() in ("and", "but", "."):  # "switch the stove on and leave the block alone": a sentence of its own
        lead = "; "
    return f"{lead}there is {thing}"


_ORDINAL_OF = {"one": "first", "1": "first", "two": "second", "2": "second", "three": "third", "3": "third"}
_ORDINAL_OF |= {"four": "fourth", "4": "fourth"}
_CLOSING = re.compile(
    r"(?:that is|that will be|that should be|and that is) (?:it|all|everything)(?: for now| thanks?(?: you)?)?|"
    r"(?:nothing|that is all|all) (?:else|further|more)|done|cheers|thanks?(?: you)?|ta"
)


def _arrow_prep(said: str | None, place: str) -> str:
    if said:
        return {"in": "into", "on": "onto", "inside": "into", "to": "onto"}.get(said, said)
    return "into" if place.split()[-1:] in ([c] for c in CONTAINERS) else "onto"


# A stack said as a thing ("a three-block tower with blue at the bottom, ..."): its levels follow, read as such.
_A_STACK = r"(?:a|an|the|one) (?:[\w-]+ )?(?:stack|tower|pile)\b"


def _gripped_by_part(text: str) -> str:
    """ "take hold of the square nut's handle and drop the nut over the peg": where to grip a thing carried after it
    (said again or as "it"), not a thing of its own: "pick up the square nut and drop the nut over the peg"."""
    m = re.match(
        r"(?:take hold of|grab|grip|hold|pick up|lift|seize|get hold of) the ([\w ]+?)'s (?:handle|grip|rim|edge)"
        r" and (?:then )?(put|place|set|drop|seat|move|lower|slide|carry|bring|fit|slip) (the (\w+ ){0,2}?(\w+)|it)"
        r"(?= (?:on|onto|over|in|into|inside|on top of|down|around)\b)",
        text,
    )
    if not m or m.group(3) != "it" and m.group(5) != m.group(1).split()[-1]:
        return text
    return f"pick up the {m.group(1)} and {m.group(2)} it{text[m.end() :]}"


def _lemma_verb(word: str) -> str:
    """ "opening" -> "open" (the lexicon's verb lemma), else the word as it is."""
    from lemminflect import getLemma

    lemmas = getLemma(word, upos="VERB")
    return lemmas[0] if lemmas else word


def _give_a(m: re.Match) -> str:
    """ "give the plate a scrub" -> "scrub the plate"; "a good scouring": the noun said as its verb's -ing form."""
    said = m.group(2)
    verb = getLemma(said, upos="VERB")[0] if said.endswith("ing") else said
    return f"{verb} {m.group(1)}" if verb in _VERB_FORMS else m.group(0)


def _gerund(text: str) -> str:
    """ "putting the cup on the plate" -> "put the cup on the plate" (after "would you mind")."""
    first, _, rest = text.partition(" ")
    if not first.endswith("ing"):
        return text
    for stem in (first[:-3], first[:-3] + "e", first[:-4]):
        if stem in _FIRST_WORDS:
            return f"{stem} {rest}".strip()
    return text


def _without_trailing(s: str) -> tuple[str, bool]:
    """`s` without its trailing remark (`_TRAILING`), and whether it had one; a step said after the remark stays
    ("..., and then, since you'll have a free hand, stand the box next to it": the box is still asked for)."""
    m = _TRAILING.search(s)
    if m is None:
        return s, False
    cut = s[m.start() :]
    for c in re.finditer(r",\s*(?:and |then |and then )?", cut[1:]):
        rest = cut[1 + c.end() :]
        if starts_with_verb(rest):
            return f"{s[: m.start()]}, then {rest}", True
    return s[: m.start()], True


def strip_article(phrase: str) -> str:
    return re.sub(r"^(?:the|a|an|this|that|my|your) ", "", phrase)


def _head(phrase: str) -> str:
    words = phrase.split()
    return words[-1] if words else ""


def _purpose(text: str) -> str:
    """Drop a trailing purpose, unless it names where the object should end up and the clause does not."""
    # "put the plate on the stove to warm it": an infinitive of purpose after the destination
    text = re.sub(
        r"\s+(?:in order )?to (\w+) (?:it|them)(?: up)?$",
        lambda m: "" if is_verb(m.group(1)) and _DESTINATION.search(text[: m.start()]) else m.group(0),
        text,
    )
    m = _PURPOSE.search(text)
    while m and _intensifier(m.group(0)):  # "if you would be so good, kindly ...": "so" says how good, not what for
        m = _PURPOSE.search(text, m.end(1) - len(m.group(1)) + 1)
    if not m:
        return text
    main, purpose = text[: m.start()], m.group(1)
    main = re.sub(r"(?<=\w) (?:over|along|across|around|round)$", "", main)  # "nudge the plate over so ...": a particle
    state = re.fullmatch(
        r"(?:it|they|that|the \w+) (?:comes?|goes|turns?|switches|is|gets?|ends? up) (on|off|open|closed|shut)", purpose
    )
    verb, _, what = main.partition(" ")
    # "turn the knob so it comes on": a turn said with no sense of its own takes the state's
    unsaid = verb in ("turn", "switch", "flip", "twist") and not re.match(r"(?:on|off)\b", what)
    if state and (unsaid or not starts_with_verb(main)) and is_verb(verb) and what:
        # a verb the list lacks, with the state it brings about: "twist the knob so it comes on" turns it on
        return f"{ACTION_WORDS[dict(STATE_ACTIONS)[state.group(1)]]} {what}"
    place = _PURPOSE_PLACE.search(purpose)
    subject = re.match(r"((?:the|a|an) [\w ]+?) (?:sits?|is|ends? up|rests?|lands?|stays?|goes)\b", purpose)
    if place and subject and not starts_with_verb(main) and is_verb(verb):
        # "swap them round so the red cube ends up on the green one": a verb the list lacks, and the goal it serves
        return f"put {subject.group(1)} {'in' if place.group(1) in ('in', 'into', 'inside') else 'on'} {place.group(2)}"
    # (of the last step said: "pick the mug up, bring it over the bowl and tip it so the beads fall into the bowl")
    last = re.split(r"\s*,\s*(?:and |then )?|\s+and (?:then )?|\s+then\s+", main)[-1]
    if place and starts_with_verb(last) and not _DESTINATION.search(last.split(" ", 1)[-1]):
        prep = {"in front of": "to the front of", "next to": "next to", "beside": "next to"}.get(place.group(1), "into")
        if place.group(1) in ("on", "onto", "on top of"):
            prep = "onto"
        return f"{main} {prep} {place.group(2)}"
    return main


def _request_after_reason(text: str) -> str:
    """ "we're clearing the table, so I'd like the plate on the cabinet": a reason that asks for nothing first, the
    request after "so" (a purpose follows a request, never stands before it)."""
    m = re.fullmatch(r"(.+?),? so (?!that\b)(.+)", text)
    if not m or _intensifier(f" so {m.group(2)}"):
        return text
    main, request = m.groups()
    subject = re.match(r"((?:the|a|an) [\w ]+?) (?:is|are|looks?|seems?)\b", main)
    if subject and starts_with_verb(request) and re.search(r"\b(?:it|them)\b", request):
        # "the drawer is open, so close it": what the reason says of a thing, then the request acting on it
        return re.sub(r"\b(?:it|them)\b", subject.group(1), request, count=1)
    if starts_with_verb(main) or _DESTINATION.search(main) or goal_to_action(main):
        return text
    if re.search(r"\b(?:it|them|that|this|these|those|one)\b", request):
        return text  # the reason names what the request acts on
    # asked in a frame ("so would you mind switching the stove on"), or as the frame left it ("switching ...")
    asked = re.match(r"(?:would you mind|could you|can you|would you|will you|please|kindly)\b", request)
    gerund = re.match(r"[a-z]+ing\b", request)
    said = _lemma_verb(gerund.group(0)) + request[gerund.end() :] if gerund else request
    if gerund and starts_with_verb(said):
        return said
    return request if starts_with_verb(request) or goal_to_action(request) or asked else text


def _intensifier(said: str) -> bool:
    """`said` (from its "so" on) is "so" before a word of degree that ends the phrase ("be so good, ...", "so kind
    as to", "so much of you"): it says how much; no purpose follows."""
    degree = re.match(r"(?:\s*,\s*|\s+)so (\w+)(?:\s*,|$| as\b| of you\b)", said)
    return degree is not None and bool({"ADJ", "ADV"} & set(getAllLemmas(degree.group(1))))


def _colon(left: str, right: str) -> list[str]:
    """ "plate: the red block", "red block: up in the gripper", "sort the blocks: red into the green tray and
    blue into the yellow tray", "a tower: blue at the bottom, green in the middle, red on top"."""
    items = [i for i in re.split(r"\s*,\s*(?:then\s+)?|\s+and\s+(?:then\s+)?|\s+then\s+", right) if i]
    tower = _tower(items)
    if tower:  # "want it the other way round: red cube on top, green cube underneath"
        return tower
    # "the basket's contents should be: X", "the basket should hold: X": the holder named on the left
    left = re.sub(r"'s? (?:contents?|load)(?: (?:should|must|will|has to|needs to) be| (?:is|are))?$", "", left)
    left = re.sub(r" (?:should|must|will|has to|needs to) (?:hold|contain|have|get)$", "", left)
    if re.search(r"\b(?:tower|stack|pile)\b", left) and re.search(r"\b(?:bottom|top)\b", left):
        # "tower from the bottom up: blue, green, red": the items in the order the left says
        order = items[::-1] if re.search(r"\bfrom the top\b|\btop (?:to|down)\b", left) else items
        return [f"stack {a} on {b}" for b, a in zip(order, order[1:])]
    if re.search(r"\btower\b", left):
        placed: dict[str, list[str]] = {"bottom": [], "middle": [], "top": []}
        for item in items:
            m = re.fullmatch(r"(.+?) (?:at the bottom|on the bottom|in the middle|on top|at the top)", item)
            if not m:
                return [f"stack {i}" for i in items]
            where = "bottom" if "bottom" in item else "middle" if "middle" in item else "top"
            placed[where].append(m.group(1))
        order = [x for k in ("bottom", "middle", "top") for x in placed[k]]
        return [f"stack {a} on {b}" for b, a in zip(order, order[1:])]
    state = _predicate(left if re.match(r"(?:the|a|an) ", left) else f"the {left}", right)
    if state and right in dict(STATE_ACTIONS):  # "drawer: open", "stove: on"
        return [state]
    if starts_with_verb(right):
        return [f"there is {left}", right]
    if re.match(r"(?:into|onto|on to|inside|in|on top of|on) ", right):  # "topmost bowl: onto the plate"
        return [f"put {left} {right}"]
    if (  # "salad dressing: basket": a thing, then the container it goes in
        len(items) == 1
        and not re.match(r"(?:the|a|an) ", right)
        and _head(right) in CONTAINERS
        and _head(left) not in CONTAINERS
    ):
        return [f"put {left} in {right}"]
    verb, _, rest = left.partition(" ")
    # a verb the list lacks, then a particle or what it acts on ("tidy up for me: ...", "arrange them: ...")
    other_verb = is_verb(verb) and re.match(
        r"(?:up|out|away|them|these|those|it|everything|things|for|(?:the|this|that) (?:order|stack|tower|pile))\b",
        rest,
    )
    if starts_with_verb(left) or other_verb:  # "sort the blocks: red into the green tray ...": each item one carry
        return [goal_to_action(i) or f"put {i}" for i in items]  # an item may state its goal ("X goes to Y")
    if right in HELD or right.startswith(("up ", "in the gripper", "in the air")):
        return [f"pick up {left}"]
    prep = "in" if _head(left) in CONTAINERS else "on"
    return [f"put {i} {prep} {left}" for i in items]


_TOWER_PLACES = (
    ("top", r"on top|at the top|on the top|uppermost|up top|last|at the end"),
    ("middle", r"in the middle|in between"),
    (
        "bottom",
        r"underneath|beneath|below|under(?: it| them)?|at the bottom|on the bottom|at the base|lowest",
    ),
)


_TOWER_HEADER = re.compile(
    r"^(?:build|make|form|create|assemble|put together|stack up|i want|i'd like|i need|we want|we need|"
    r"(?:you should |we should |i want to |let's )?(?:end|finish|wind) up with|(?:end|finish) with)(?: me)? "
    r"(?:a|the|one) (?:[\w-]+ )?(?:tower|stack|pile)"
    r"(?: (?:out )?of (?:the |all )?(?:three |two |all )?(?:blocks|cubes|three|them|these))?"
    r"(?:\s*[-:]\s*|\s+(?:with|where|that has)\s+|\s*)"
)
# A word that makes a clause of a noun phrase ("the red block should end up in the air"): a goal said in words.
_SAYS_GOAL = r"\b(?:should|must|will|would|could|can|needs?|has|have|is|are|be|ends?|gets?|goes|go|wants?|ought)\b"


def _tower(items: list[str]) -> list[str] | None:
    """Items that each say where a thing sits in a stack ("red cube on top", "green cube underneath"): the stack
    from the bottom up, or None when an item says no place in a stack or none is at the top or the bottom."""
    placed: dict[str, list[str]] = {"top": [], "middle": [], "bottom": []}
    items = [re.sub(r"^(?:and )?(?:then|next|after that)\s+", "", i.strip()) for i in items if i.strip()]
    if items:  # "build a tower - blue on the bottom, ...": the stack named first, its order after
        items[0] = _TOWER_HEADER.sub("", items[0])
        # "three-block tower, blue at the bottom, ...": the tower named without a verb (after a header: "goal: ...")
        items[0] = re.sub(r"^(?:a |the |one )?(?:[\w-]+ )?tower$", "", items[0])
        items = [i for i in items if i] if len(items) > 1 else items  # "make a tower, blue first, ..."
    counted = _tower_by_ordinals(items)
    if counted:  # "blue first, green second, red third"
        return counted
    for item in items:
        for where, words in _TOWER_PLACES:
            m = re.fullmatch(rf"((?:the |a |an )?[\w ]+?) (?:(?:is|sits|goes|should be|should go) )?(?:{words})", item)
            if m and _is_noun_phrase(m.group(1)):
                placed[where].append(m.group(1))
                break
        else:
            # a thing said with no place between the bottom and the top ("blue on the bottom, then green, then
            # red on top"): it goes where it was said, in the middle
            if not (placed["bottom"] and not placed["top"] and _is_noun_phrase(item) and not starts_with_verb(item)):
                return None
            placed["middle"].append(item)
    order = [x for k in ("bottom", "middle", "top") for x in placed[k]]
    if len(order) < 2 or len(placed["top"]) > 1 or len(placed["bottom"]) > 1 or not (placed["top"] or placed["bottom"]):
        return None
    return [f"stack {a} on {b}" for b, a in zip(order, order[1:])]


_ORDINALS = ("first", "second", "third", "fourth")
_PLACE_ONLY = re.compile(
    r"(?:(?:at|on|as|in) )?(?:the )?(?:very )?(?:top|bottom|base|middle|foundation)(?: (?:one|layer|level))?"
)
_BOTTOM = r"(?:(?:at|on|as) )?the (?:base|bottom|foundation)|(?:at the )?bottom"
_TOP = r"(?:(?:at|on) )?the (?:very )?top|on top|(?:at the )?top|last"


def _tower_by_ordinals(items: list[str]) -> list[str] | None:
    """ "the blue block is first (the base), the green block is second, and the red block goes third, at the very
    top": a stack counted from the bottom up ("first" itself is gone by now, a filler: the first item, or the one
    said to be the base, is the bottom); an item that only restates a place ("at the very top") is dropped. None
    unless some item says "second" and every other item is a thing with its own rank."""
    said: list[tuple[str, str | None]] = []  # (thing, its ordinal, "bottom", "top" or None)
    for n, item in enumerate(re.sub(r"^and ", "", i) for i in items):
        m = re.fullmatch(
            rf"((?:the |a |an )?[\w ]+?)(?: (?:(?:is|goes|sits|comes|should be|should go) )?"
            rf"({'|'.join(_ORDINALS)}|{_BOTTOM}|{_TOP})(?: (?:{_PLACE_ONLY.pattern}))?)?",
            item,
        )
        if m and _is_noun_phrase(m.group(1)) and (m.group(2) or n == 0):
            said.append((m.group(1), m.group(2)))
        elif not _PLACE_ONLY.fullmatch(item):
            return None
    if not any(rank == "second" for _, rank in said):
        return None
    ranks = [
        0
        if rank is None or re.fullmatch(_BOTTOM, rank)
        else len(said) - 1
        if re.fullmatch(_TOP, rank)
        else _ORDINALS.index(rank)
        for _, rank in said
    ]
    if sorted(ranks) != list(range(len(said))):
        return None
    order = [thing for _, (thing, _) in sorted(zip(ranks, said))]
    return [f"stack {a} on {b}" for b, a in zip(order, order[1:])]


def _holds(text: str) -> str | None:
    """ "the basket should contain the block", "the plate needs the block on it": a carry into the holder."""
    modals = "|".join(re.escape(m) for m in sorted(MODALS, key=len, reverse=True))
    holds = "|".join(re.escape(h) for h in HOLDS)
    m = re.fullmatch(
        rf"((?:(?:the|a|an|this|that|my|your) )?[\w' ]+?)\s+(?:(?:{modals})\s+)?(?:{holds})\s+"
        r"((?:the|a|an|both|all|some) [\w' ]+?)(?:\s+(?:sitting|resting|standing|lying|placed|stacked|set|put))?"
        r"(?:\s+(in|on|inside|on top of|into|onto) (?:it|them))?",
        text,
    )
    if not m:
        return None
    holder, thing, prep = m.group(1), m.group(2), m.group(3)
    if not _is_noun_phrase(holder):
        return None
    if prep is None and re.fullmatch(rf"(?:a|an) (?:\w+ )?(?:{'|'.join(sorted(PARTS))})", thing):
        return None  # "the cabinet has a drawer": one of its parts (perception's parts table), said to be there
    if prep is None:
        prep = "in" if _head(holder) in CONTAINERS else "on"
    return f"put {thing} {'in' if prep in ('in', 'inside', 'into') else 'on'} {holder}"


def _with_on_it(text: str) -> str | None:
    """ "the plate with the red block on it", "a bowl with the apple in it": the thing after "with" goes there."""
    m = re.fullmatch(r"(.+?) with (.+?) (on top of|on|in|inside) (?:it|them)", text)
    if not m or not _is_noun_phrase(m.group(1)) or not _is_noun_phrase(m.group(2)):
        return None
    return f"put {m.group(2)} {'in' if m.group(3) in ('in', 'inside') else 'on'} {m.group(1)}"


# Words that start a clause without being a noun phrase: a goal is said of a thing, not of these.
_NOT_SUBJECT = (
    r"(?:i|you|we|he|she|they|there|here|what|which|who|how|why|when|where|let|do|does|can|could|would|will|should|"
    r"if|so|and|but|or|not|no|please|thanks?|it is|that is)\b"
)


def _is_noun_phrase(text: str) -> bool:
    """A noun phrase, with or without its article ("the red block", "red block", "alphabet soup")."""
    det = r"(?:the|a|an|this|that|these|those|both|my|your|some|all(?: the)?) "
    if re.match(det, text):
        return re.fullmatch(rf"{det}[\w' ]+", text) is not None
    # without an article: a few words, none of them a function word ("someone left the drawer" is a clause)
    words = text.split()
    inner = r"(?:the|a|an|in|on|into|onto|of|to|from|with|at|by|is|are|was|were|be|and|or|it|them)"
    return (
        0 < len(words) <= 4
        and re.fullmatch(r"[\w' ]+", text) is not None
        and re.match(_NOT_SUBJECT, text) is None
        and not any(re.fullmatch(inner, w) for w in words)
    )


def bare_goal(text: str) -> str | None:
    """A goal said as a noun phrase and a place, with no verb at all ("red block in the cabinet drawer", "wine
    bottle in the bowl", "the plate with the red block on it"): a carry to the last place named. The mentions are
    found first; the relation word between them gives the roles."""
    held = _with_on_it(text)
    if held:
        return held
    # a thing that goes around another is put on it ("the nut around the peg")
    text = re.sub(r"\baround (?=(?:the|a|an) )", "onto ", text)
    # "to" without a verb is a direction, not a place ("fly to the moon"): only words that say in or on
    places = [m for m in _DESTINATION.finditer(text) if m.group(1) not in ("to", "over")]
    if not places:
        return None
    return _predicate(text[: places[-1].start()].strip(), text[places[-1].start() :])


def goal_to_action(text: str) -> str | None:
    """The imperative for a stated goal, or None when `text` states none this reader knows. Tried in turn: a goal
    verb ("belongs", "should be"), a state ("the stove on") or a participle ("the cup placed on the saucer"), a
    bare "is" ("make sure the cup is on the saucer"), a wish naming a place ("I want the cup on the saucer")."""
    said = re.fullmatch(
        r"(?:it|this|that|the (?:end |final )?(?:state|goal|result)) (?:should|must|has to|needs to|will) "
        r"(?:be|look like|end up(?: as)?)\s+(.+)",
        text,
    )
    if said:  # "it should be red on top of green": the goal is the thing and place after it
        return bare_goal(said.group(1))
    wish = re.fullmatch(r"(?:i|we) (?:want|need)\s+(.+)", text)
    body = wish.group(1) if wish else text
    both = body.split(" and ")
    # (or a state: "i want the top drawer open and the black bowl inside it")
    stated = re.compile(r"\b(?:open|opened|closed|shut|on|off)\s*[.!]*$")
    if wish and len(both) > 1 and all(_DESTINATION.search(b) or stated.search(b) for b in both):
        # "i want red in the green tray and blue in the yellow tray": one carry per goal
        steps = [goal_to_action(f"i want {b}") for b in both]
        return ", ".join(x for x in steps if x) if all(steps) else None
    listed = re.split(r"\s*[,;]\s*(?:and\s+)?|\s+and\s+", body)
    if not wish and len(listed) > 1:
        # "the green tray holds the red block and the yellow tray holds the blue one" (or ", the yellow tray ..."):
        # one carry per goal, when every part states one
        steps = [goal_to_action(b) for b in listed]
        if all(steps):
            return ", ".join(x for x in steps if x)
    held = _holds(body)
    if held:
        return held
    copulas = "|".join(re.escape(c) for c in sorted(COPULAS, key=len, reverse=True))
    states = "|".join(re.escape(s) for s, _ in STATE_ACTIONS)
    parts = "|".join(re.escape(p) for p in sorted(PARTICIPLES, key=len, reverse=True))
    for pattern in (
        rf"(.+?)\s+(?:{copulas})(?:\s+be)?\s*(.*)",
        r"(.+?)\s+(?:is|are)\s+(.*)",
        rf"(.+?)\s+((?:{parts})\b.*)",
        rf"(.+?)\s+({states})",
    ):
        m = re.fullmatch(pattern, body)
        action = _predicate(m.group(1).strip(), m.group(2).strip()) if m else None
        if action:
            return action
    places = list(_DESTINATION.finditer(body)) if wish else []
    if places:  # "I want the cup on the saucer": a carry to the last place named
        return _predicate(body[: places[-1].start()].strip(), body[places[-1].start() :])
    return None


def _predicate(subject: str, predicate: str) -> str | None:
    # "the jug winds up in the crate": a phrasal verb the goal words lack, between the thing and its place
    verb = re.fullmatch(r"(.+?) (\w+) (?:up|down|out)", subject)
    # ("the red block up in the gripper": "up" there says it is lifted, and "block" is the thing's noun)
    lifted = subject.endswith(" up") and re.match(r"(?:up )?in the (?:gripper|air|hand)\b", predicate)
    if verb and not lifted and is_verb(verb.group(2)) and _is_noun_phrase(verb.group(1)):
        subject = verb.group(1)
    if not (_is_noun_phrase(subject) or subject in ("it", "they", "that one", "this one")):
        return None  # a goal is said of a noun phrase ("the apple belongs ..."), not of a word salad
    if re.search(r"\b(?:in|on|into|onto|of|to|the|a|an|(?:which|that|who)(?: is| are)?)$", subject):
        return None  # "the bowl which is on the stove" names a bowl: it states no goal
    state = dict(STATE_ACTIONS).get(predicate)
    if state:
        return f"{ACTION_WORDS[state]} {subject}"
    # ("up" before a place is where it ends up: "should finish up inside the green area")
    place = r"(?:in|inside|into|on|onto|at|in front of|next to|by|near|beside|under)\b"
    predicate = re.sub(rf"^up (?={place})", "", predicate)
    if predicate in HELD or re.match(
        r"(?:up\b|in the air|in the gripper|held|lifted|raised|picked up|(?:off|clear of) the (?:table|surface)\b)",
        predicate,
    ):
        return f"pick up {subject}"
    action = "put"
    for participle in sorted(PARTICIPLES, key=len, reverse=True):
        if predicate == participle or predicate.startswith(participle + " "):
            action, predicate = PARTICIPLES[participle], predicate[len(participle) :].strip()
            break
    predicate = re.sub(r"^(?:down|up|back|away|over|safely|neatly)\s+", "", predicate)
    if action == "pick":
        return f"pick up {subject}"
    if predicate.startswith("in front of"):
        return f"push {subject} to the front of {predicate[len('in front of') :].strip()}"
    if action == "put" and (
        _head(subject) in CONTENTS
        or re.search(r"'s? (?:contents?|beads)$", subject)
        or re.match(rf"{CONTENTS_SAID}(?:{'|'.join(CONTENTS)}) (?:from|in|of|out of) ", subject)
    ):
        action = "pour"
    if not predicate or not _DESTINATION.match(predicate) and action in ("put", "stack", "pour"):
        return None
    return f"{ACTION_WORDS[action]} {subject} {predicate}"


# Said of a robot's second arm: a task for two arms ("with both arms", "each hand", "to the other arm").
_ARMS = re.compile(r"\b(?:both|two|each|either|one|second|other|left|right) (?:arms?|hands?|grippers?)\b")
_TWO_HANDLES = re.compile(r"\b(?:both|two|each) (?:arms?|hands?|handles?)\b|\bhandles?\b[^.]*\beach side\b")
_LIFT = re.compile(r"\b(?:lift|lifts|lifted|raise|raised|hoist|heave|hold up|pick up|pick it up|pick them up|up)\b")
_GIVE = re.compile(
    r"\b(?:hand|hands|pass|passes|give|gives|transfer|transfers|move|switch|swap|shift)\b[^.]*?"
    r"\b(?:to|into|over to|across to|across into) (?:the |your )?(other|left|right|second)"
    # ("hand it off to the other": the arm left unsaid at the end)
    r"(?: (?:one|arm|hand|gripper)\b|(?=\s*(?:[.!,;]|$)))|"
    r"\bso (?:that )?the (other|left|right|second) (?:arm|hand|gripper) (?:ends up holding|holds|has|takes|gets)\b"
)
# Any other step: a two-arm reading is only for an instruction that says nothing else to do.
_OTHER_STEP = re.compile(r"\b(?:put|place|set|drop|stack|open|close|shut|turn|push|pour|wipe|scrub|slide|insert)\b")
_NOT_CARRIED = frozenset(["arm", "arms", "hand", "hands", "gripper", "grippers", "handle", "handles", "side", "sides"])


def _two_arms(said: list[str]) -> list[str] | None:
    """A two-arm task read from its cues wherever they are said: a lift by both arms or by the thing's two handles
    ("the pot has a handle on each side; grab one with each arm and lift it", "with both arms, grab the pot's handles
    and raise it"), or a handover to the other arm ("grab the hammer with one arm, then pass it over so the other arm
    ends up holding it"). None when no second arm or pair of handles is said, or another step is."""
    text = " . ".join(said)
    if not _ARMS.search(text) and not _TWO_HANDLES.search(text) or _OTHER_STEP.search(text):
        return None
    thing = _carried_thing(text)
    header = re.match(r"([a-z]+(?: [a-z]+)?)\s*:\s", text)  # "hammer: pick it up with one arm, then ..."
    if thing is None and header and header.group(1).split()[-1] not in _NOT_CARRIED:
        thing = header.group(1)
    if thing is None:
        return None
    give = _GIVE.search(text)
    if give:
        receiver = give.group(1) or give.group(2)
        receiver = "other" if receiver == "second" else receiver
        giver = re.search(r"\bwith (?:the |your |its )?(right|left|one) (?:arm|hand|gripper)\b", text)
        return [f"pick up the {thing} with the {giver.group(1) if giver else 'one'} arm for the {receiver} arm"]
    # by its handles, named: without them a lift "with both hands" stays one pick of the thing
    if _TWO_HANDLES.search(text) and re.search(r"\bhandles?\b", text) and _LIFT.search(text):
        return [f"pick up the {side} {thing} handle with both arms" for side in ("left", "right")]
    return None


_NOT_A_THING_FIRST = frozenset(
    ["other", "one", "left", "right", "second", "two", "is", "are", "was", "were", "has", "will", "would", "should"]
    + ["can", "could", "it", "way"]
)


def _carried_thing(text: str) -> str | None:
    """The first thing named that is no arm, hand or handle ("the hammer's handle" names the hammer)."""
    for m in re.finditer(
        r"\b(?:the|a|an|its|that|this) ([\w ]+?)(?:'s\b|(?= (?:by|with|and|to|on|in|from|of|so|then|for|"
        r"across|over|using|has|is|lifted|raised|held|picked|up|off)\b)|\s*$|\s*[,.;:])",
        text,
    ):
        words = m.group(1).split()
        if words[-1] in ("handle", "handles") and len(words) > 1:  # "the pot handles": the pot's
            words = words[:-1]
        # ("see that pot?": a thing pointed at; "that is ...": no thing)
        if words[-1] not in _NOT_CARRIED and words[0] not in _NOT_A_THING_FIRST:
            return " ".join(words)
    return None


def imperatives(instruction: str) -> list[str]:
    """The instruction as a list of imperative strings (each may still hold several clauses)."""
    out: list[str] = []
    said = sentences(instruction)
    both_arms = _two_arms(said)
    if both_arms:
        return both_arms
    for i, sentence in enumerate(said):
        s = _gerund(re.sub(r"^(?:make sure|ensure|see to it|check) (?:that )?(?=the |a |an )", "", sentence))
        # "the plate's sitting on the stove at the moment; put the bowl on it": where a thing is now, said before the
        # request, describes it (a goal would come last)
        if i < len(said) - 1:
            s = re.sub(
                r"^((?:the|a|an) [\w ]+?) (?:is|are) (?:sitting|resting|standing|lying|located|kept|parked|perched|"
                r"waiting|stacked|sat|placed) ((?:on|in|inside|on top of|at|by|near|next to|beside|between|under|"
                r"underneath|beneath) "
                r"[\w ]+?)"
                r"(?: (?:at the moment|right now|right|currently|for now|now))?$",
                r"there is \1 \2",
                s,
            )
            # "the cabinet at the back has a single drawer. open it": the part named by its whole, then acted on
            if re.search(r"\b(?:it|them|there)\b", said[i + 1]) and starts_with_verb(said[i + 1]):
                s = re.sub(
                    r"^((?:the|that|this) [\w ]+?) (?:has|has got) (?:a|an|one|a single|just one|only one) "
                    r"(drawer|handle|door|lid|knob)(?:,? and (?:it|that) is (?:shut|closed|open|out|in))?$",
                    r"there is the \2 of \1",
                    s,
                )
            # "the drawer is open; close it": the state it is in now, before the request that changes it
            if starts_with_verb(said[i + 1]):
                s = re.sub(
                    r"^((?:the|a|an) [\w ]+?) (?:is|are) (?:currently |still |now |already |left )?"
                    r"(?:open|opened|closed|shut|on|off|running|sticking out|pulled out|out)$",
                    r"there is \1",
                    s,
                )
            # "the beads are in the mug. pour them into the bowl": said as it is now, then acted on by a pronoun
            if re.search(r"\b(?:it|them)\b", said[i + 1]) and starts_with_verb(said[i + 1]):
                s = re.sub(
                    r"^((?:the|a|an) [\w ]+?) (?:is|are) ((?:on|in|inside|on top of|at|by|near|next to|beside|under|"
                    r"underneath|beneath) "
                    r"(?:the|a|an) [\w ]+?)(?: (?:at the moment|right now|right|currently|for now|now))?$",
                    r"there is \1 \2",
                    s,
                )
        # "the mug has beads in it, pour them ...": a container named with what it holds, then acted on (a
        # substance it is said to hold stays said: the scene must show it, rules/kinds.py)
        # ("the mug has beads in it. tip them out into the bowl": the same, said as a sentence of its own)
        acted_on = (
            i < len(said) - 1 and bool(re.search(r"\b(?:it|them)\b", said[i + 1])) and starts_with_verb(said[i + 1])
        )
        s = re.sub(
            rf"^((?:the|a|an) [\w ]+?) (?:has|holds|contains|is full of) (?:some |the )?{_SMALL}(?:"
            + "|".join(c for c in CONTENTS if c not in SUBSTANCES)
            + r")(?: in (?:it|there))?(?:\s*,\s*(?=\w)"
            + ("|$)" if acted_on else ")"),
            r"there is \1, ",
            s,
        ).rstrip(", ")
        if acted_on:  # "there are beads in the mug. tip them out ...": the holder is what is named, then poured
            s = re.sub(
                rf"^there (?:are|is) (?:some |the |a few )?{_SMALL}(?:"
                + "|".join(c for c in CONTENTS if c not in SUBSTANCES)
                + r") (?:in|inside) ((?:the|a|an) [\w ]+)$",
                r"there is \1",
                s,
            )
        # "see the red block? put it on the plate": pointing a thing out names it for what follows
        s = re.sub(
            r"^(?:do you |can you )?(?:see|notice|spot|you see|you can see|you will see|you will find) "
            r"(?=(?:the|a|an|that|this) )",
            "there is ",
            s,
        )
        first = re.fullmatch(
            r"(.+?),? (?:which|so|and|then) (?:you (?:will |would )?(?:need to|have to|must|should) )?open"
            r"(?: it| that)?(?: first| beforehand| before that)?",
            s,
        )
        into = re.search(r"\b(?:in|into|inside) (?:the )?(.+?)$", first.group(1)) if first else None
        holder = re.match(r"put .+ in (.+)$", _holds(first.group(1)) or "") if first else None
        if first and (into or holder):  # "the bowl should end up in the top drawer, which you'll need to open first"
            out.append(f"open the {into.group(1) if into else strip_article(holder.group(1) if holder else '')}")
            s = first.group(1)
        s = re.sub(r"^the other (.+?),? not the one (.+?),\s*", r"the \1 not \2 ", s)
        s = re.sub(r",?\s*the one (?:on|sitting on|lying on|that is on) the table,?", " ", s).strip()
        # a remark about the thing after a comma ("..., it dents", "..., they are fragile"): no step, no place
        s = re.sub(
            r",\s*(?:because |since |as )?(?:it|they) (?!(?:goes|go|belongs?|should|must|needs?|has|have|wants?|will|"
            r"is to|are to|ought)\b)(?:is|are|\w+s)\b(?![^,]*\b(?:on|in|into|onto|inside|on top of) (?:the|a|an)\b)"
            r"[^,]*$",
            "",
            s,
        )
        # "open the drawer, all the way out": how far, after the action
        if starts_with_verb(s):
            s = re.sub(r",\s*(?:all the way )?(?:out|open|shut|closed)\b(?:\s+if (?:you can|possible))?\s*$", "", s)
        s = _GRIP.sub("", _NOT_THERE.sub("", _request_after_reason(_gripped_by_part(s))))
        for _ in range(3):  # remarks said one after another (", when you've got a sec, no rush"): the last goes first
            s, cut = _without_trailing(s)
            if not cut:
                break
        # "red block up, in the gripper", "red cube up and still held": a thing lifted and held
        lifted = re.fullmatch(
            r"((?:the |a |an )?[\w ]+?) up,?\s*(?:and )?(?:(?:still|now|held|kept|safely) )*"
            r"(?:in (?:the|your) (?:gripper|hand|fingers)|in the air|held(?: up)?)",
            s,
        )
        if lifted and _is_noun_phrase(lifted.group(1)) and not re.search(_SAYS_GOAL, lifted.group(1)):
            out.append(f"pick up {lifted.group(1)}")
            continue
        # (said as a wish: "i want red on top, green underneath")
        wish = re.sub(rf"^(?:i|we) (?:want|need|would like|'d like) (?!{_A_STACK})", "", s)
        tower = _tower(re.split(r"\s*,\s*|\s+and\s+", wish))
        if tower:  # "red cube on top, green cube underneath": a stack said by where each one is
            out += tower
            continue
        s = _purpose(s)
        if ":" in s:
            left, right = (x.strip() for x in s.split(":", 1))
            out += _colon(left, right)
            continue
        # "the soup tin, into the basket": a thing named, then only where it goes
        where = re.fullmatch(
            r"([^,]+),\s*(?:(?:up|down|over|back|upright) )?((?:into|onto|on to|inside|in|on top of|on|in front of|to) "
            r"[^,]+)",
            s,
        )
        if where and _is_noun_phrase(where.group(1)) and not starts_with_verb(where.group(1)):
            front = where.group(2).startswith("in front of")  # "the plate, in front of the stove": pushed there
            place = f"to the front of{where.group(2)[len('in front of') :]}" if front else where.group(2)
            out.append(f"{'push' if front else 'put'} {where.group(1)} {place}")
            continue
        pair = re.fullmatch(r"([^,]+),\s*([^,]+)", s)
        if pair and (pair.group(2) in dict(STATE_ACTIONS) or pair.group(2) in HELD):
            out += _colon(pair.group(1), pair.group(2))  # "cabinet drawer, opened": the thing, then its state
            continue
        if (
            pair
            and not any(starts_with_verb(x) or _DESTINATION.search(x) for x in pair.groups())
            and not all(goal_to_action(x) for x in pair.groups())  # "the green tray gets X, the yellow tray Y"
        ):
            out += _colon(pair.group(2), pair.group(1))  # "green block, basket"
            continue
        # "the bowl sitting on the box, put it on the plate": a thing named first, then acted on through a pronoun
        topic = re.fullmatch(r"([^,]+),\s*(.+)", s)
        named_first = bool(
            topic and starts_with_verb(topic.group(2)) and re.search(r"\b(?:it|them|that|this)\b", topic.group(2))
        )
        if not starts_with_verb(s) and not named_first:
            opened = re.search(r"\b(?:in|into|inside) the open (\w+(?: \w+)?)$", s)
            goal = goal_to_action(re.sub(r"\bthe open\b", "the", s))
            if goal:
                if opened:
                    out.append(f"open the {opened.group(1)}")
                s = goal
        out.append(s)
    return [s for s in out if s]
