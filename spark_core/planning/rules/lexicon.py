"""Words the rules planner understands: verbs (with synonyms), prepositions, directions, and the small closed
word classes it needs to read goals, trailing clauses and noun phrases."""

from __future__ import annotations

# action -> surface forms (matching picks the longest form that starts the clause)
VERBS: dict[str, tuple[str, ...]] = {
    "pick": (
        "pick up",
        "pick",
        "lift up",
        "lift",
        "grab",
        "grasp",
        "take",
        "raise",
        "hold up",
        "get",
        "find",
        "locate",
        "reach for",
        "fetch",
        "retrieve",
        "seize",
        "collect",
        "hoist",
        "elevate",
        "choose",
        "select",
        # other English verbs of taking hold
        "snatch",
        "pluck",
        "scoop up",
        "clutch",
        # taking it away from where it is ("remove the bowl from the cabinet top and put it on the plate")
        "remove",
    ),
    "put": (
        "put",
        "place",
        "set",
        "move",
        "drop",
        "transfer",
        "bring",
        "carry",
        "relocate",
        "store",
        "stick",
        "lay",
        "toss",
        "pop",
        "fit",
        "stash",
        "tuck",
        "insert",
        "load",
        "pack",
        "return",
        "position",
        "deposit",
        "rest",
        "sit",
        "stand",
        "hang",
        "leave",
        # other English verbs of moving a thing somewhere (a general list, not the corpus's words)
        "shift",
        "stow",
        "haul",
        "lug",
        "plonk",
        "plop",
        "plunk",
        "park",
        "chuck",
        "throw",
        "lob",
        "ferry",
        "convey",
        "transport",
        "deliver",
        "send",
        "slot",
        "stuff",
        "cram",
        "nestle",
        "hide",
        "lodge",
        "settle",
        "slip",
        "plant",
        "perch",
        "situate",
        # lowering a thing held onto a place sets it there
        "lower",
        "lower down",
    ),
    "stack": ("stack", "pile"),
    "push": ("push", "shove", "nudge", "slide", "scoot", "bump", "budge", "poke"),
    "open": ("open", "pull open", "slide open", "pull out", "draw out", "haul open", "yank open", "swing open"),
    "close": (
        *("close", "shut", "push closed", "push shut", "slam", "slam shut"),
        *("slide closed", "slide shut", "pull closed", "pull shut", "swing shut", "ease shut", "ease closed"),
    ),
    "turn_on": ("turn on", "switch on", "ignite", "start", "light", "fire up", "power on", "activate", "heat up"),
    "turn_off": ("turn off", "switch off", "power off", "shut off", "deactivate", "extinguish", "shut down", "kill"),
    "pour": ("pour", "empty", "tip", "dump", "tilt", "decant"),
    "scrub": ("scrub", "wipe", "clean", "scour", "wash", "rub", "polish", "buff", "mop"),
    "sort": ("sort",),
}
# Things that scrub: the one the scene holds is the tool of a scrub said without one ("plate clean").
CLEANERS = ("sponge", "cloth", "rag", "towel", "brush", "scrubber", "scourer", "pad")
# What a cleaning goal removes, said in any of its words ("no grime left", "get the muck off the table"): a regex
# alternative
DIRT = r"(?:dirt|dust|mess|crumbs|stains?|spills?|smudges?|marks?|grime|muck|gunk|crud|filth)"
# Verb forms whose object comes after a particle ("pick the block up", "turn the stove on").
PARTICLE_VERBS = {"pick": "up", "turn_on": "on", "turn_off": "off", "lift": "up"}
ON = ("on top of", "onto", "on to", "atop", "on", "over")
IN = ("into", "inside of", "inside", "within", "in")
WITH = ("with", "using")
FROM = ("from", "out of")
DIRECTIONS: dict[str, tuple[str, ...]] = {
    "forward": ("forward", "forwards", "away from the robot", "away from you", "ahead", "further away", "to the back"),
    "backward": (
        "backward",
        "backwards",
        "toward the robot",
        "towards the robot",
        "toward you",
        "towards you",
        "closer",
    ),
    "left": ("to the left", "left", "leftward", "leftwards"),
    "right": ("to the right", "right", "rightward", "rightwards"),
}
DETERMINERS = ("the", "a", "an", "this", "that", "these", "those", "some", "all", "both")
PRONOUNS = ("it", "them", "there", "that one", "this one")
# The speaker's own plans, said after the request (a pattern part, no step): what they will do once it is done
# ("... so i can see what's inside", "... before we put anything on it", "..., after this i do the rest").
SPEAKERS_PLANS = (
    r"(?:so (?:that )?|before |after |until )(?:(?:this|that|it),? )?(?:i|we) (?:can |could |may |might |will |'ll )?"
    r"[a-z]+\b"
)
# Why, or what is coming, said after a comma ("..., just want to see if the grasp holds", "..., we have a demo").
SPEAKERS_REASON = (
    r"(?:i )?(?:just |only )?(?:want|wanna|need|would like) to (?:see|check|test|know|verify|find out)\b|"
    r"(?:we|i) (?:have|have got) (?:a|an|some|guests|visitors|company)\b|"
    # a worry about the thing ("..., since the carton might tip over")
    r"(?:since|because|as) the \w+(?: \w+)? (?:might|could|may|can|tends to|is likely to|will probably)\b|"
    # what the speakers are up to, or what happens if it is not done ("..., we're packing for a picnic",
    # "..., otherwise somebody will knock it over")
    # (not when a step may follow: "..., we are packing for lunch and the banana too" still asks for the banana)
    r"(?:we|i) (?:are|am) (?:[a-z]+ing) (?:for|to|out|away|up|later|tonight|tomorrow|soon|now|a|an|some)\b"
    r"(?![^,]*\b(?:and|then|also|too|plus)\b)|"
    r"otherwise\b|or else\b"
)
# Words and phrases that carry no action. ("then" is not one: it separates clauses.)
FILLERS = (
    "please",
    "pls",
    "plz",
    "obviously",
    "of course",
    "kindly",
    "carefully",
    "gently",
    "slowly",
    "quickly",
    "now",
    "also",
    "first",
    "finally",
    "next",
    "can you",
    "could you",
    # a learner's "would you mind to open", "may you open" (the request asked as leave)
    "would you mind to",
    "do you mind to",
    "may you",
    "would you mind",
    "would you be so kind as to",
    "would you be kind enough to",
    "be so kind as to",
    "be so good as to",
    "if you please",
    # a request put as a favour ("could you be a dear and switch the stove on")
    *(
        f"be {a} and"
        for a in (
            "a dear",
            "a love",
            "a darling",
            "an angel",
            "a sweetheart",
            "a pal",
            "a sport",
            "a star",
            "a gem",
            "a hero",
        )
    ),
    "would you be able to",
    "could you be able to",
    "are you able to",
    "will you be able to",
    "would you",
    "will you",
    # asking leave to ask ("could I trouble you to switch the stove on")
    *(f"{m} i {v} you to" for m in ("could", "can", "may", "might") for v in ("trouble", "bother", "ask", "get")),
    "i want you to",
    "i need you to",
    "i would like you to",
    "would it be possible to",
    "is it possible to",
    "try to",
    "be sure to",
    "remember to",
    "you should",
    "you need to",
    "we need to",
    "we should",
    "we have to",
    "we must",
    "you have to",
    "you must",
    "let us",
    "thank you",
    "thanks",
    "go ahead and",
    # chat closings and address ("... real quick fam", "... pls ty")
    "real quick",
    "yo",
    "fam",
    "ty",
    "tysm",
    "lol",
    "lmao",
    "haha",
    "fr",
    "quick quick",
    "can or not",
    "breathe in and",
    "breathe out and",
    "breathe in",
    "breathe out",
    "can u",
    "could u",
    "would u",
    "will u",
    # interjections and sentence particles ("psst", "ah", Singapore English "lah", "lor")
    "psst",
    "ugh",
    "ah",
    "oh",
    "eh",
    "lah",
    "lor",
    "matey",
    "would ya",
    "bro",
    "dude",
    "robot,",
    "for me",
    # when it is to be done ("at your earliest convenience", "upon completion, the ... shall rest ...")
    "at your earliest convenience",
    "at your convenience",
    "upon completion",
    "on completion",
    # ... said by the run it is done in ("stove off by the end of the episode")
    *(
        f"{when} {run}"
        for when in (
            "by the end of the",
            "by the end of this",
            "by end of",
            "at the end of the",
            "before the end of the",
        )
        for run in ("episode", "run", "trial", "rollout", "demo", "session")
    ),
    *(f"before the {run} ends" for run in ("episode", "run", "trial", "rollout", "demo", "session")),
    "when done",
    "when you're done",
    "when you are done",
    "when finished",
    "when you're finished",
    "when you are finished",
    "when you finish",
    "once you finish",
    "by the time you finish",
    "once done",
    "once finished",
    "all the way",
    "fully",
    "up there",
    "over there",
)
# Things that hold other things: "to the basket" means into it; "basket: the butter" puts the butter in it.
CONTAINERS = ("bowl", "basket", "tray", "drawer", "box", "bin", "mug", "cup", "pot", "hamper", "jar", "crate", "sink")
# Kinds fixed in place, or too big for one arm to carry: never the thing picked, carried, pushed or poured ("put
# the stove on the plate"), only a place or what is worked (a drawer opened, a knob turned).
FIXED: tuple[str, ...] = ("cabinet", "stove", "table", "counter", "shelf", "sink", "fridge", "oven", "microwave")
FIXED += ("cupboard", "drawer", "dishwasher", "wall", "floor", "rack", "hob", "burner", "cooktop", "cooker")
FIXED += ("peg", "post")  # a nut assembly's pegs stand fixed in the table
# Kinds that are solid through: nothing goes inside one ("put the basket inside the green block").
SOLIDS = ("block", "cube", "brick", "ball", "butter", "hammer")
# Flat regions an object is pushed into rather than carried to.
REGIONS = ("area", "zone", "region", "square", "spot", "mark")
# Surfaces the objects stand on anyway: "off the table" or "from the table" says nothing about which object.
TABLE = ("table", "tabletop", "table top", "table surface", "counter", "where it is", "where it sits", "its place")
# Parts of an object that name the object itself as a destination ("the plate's centre" is the plate).
SELF_PARTS = (
    *("centre", "center", "middle", "surface", "top face", "top side", "top surface", "inside", "interior"),
    *("insides", "belly", "hollow", "innards"),
)
# What a container holds: "the mug's beads", "the mug's contents" pour from the mug.
CONTENTS = ("contents", "content", "beads", "balls", "pellets", "liquid", "water")
# What may come before the contents' noun: a quantifier and up to three words of their own ("all those little yellow
# beads"), never a preposition (not "the cube in the water").
CONTENTS_SAID = (
    r"(?:(?:the|some|all|all the|all those|all these|all of the|those|these) )?"
    r"(?:(?!(?:in|on|into|onto|from|of|to|with|and|the|a|an|out)\b)[a-z]+ ){0,3}?"
)
# Contents that are a substance, not rigid things: a scene shows none, so saying a container holds one is a claim
# the scene must bear out (rules/kinds.py), never read past.
SUBSTANCES = ("water",)
# Goal words after the object: the state the instruction wants, and the action that makes it.
STATE_ACTIONS: tuple[tuple[str, str], ...] = (
    ("switched on", "turn_on"),
    ("turned on", "turn_on"),
    ("switched off", "turn_off"),
    ("turned off", "turn_off"),
    ("pulled open", "open"),
    ("pulled out", "open"),
    ("slid out", "open"),
    ("extended", "open"),  # a drawer's travel: "drawer fully extended"
    ("retracted", "close"),
    ("pushed in", "close"),
    ("pushed shut", "close"),
    ("opened", "open"),
    ("open", "open"),
    ("closed", "close"),
    ("shut", "close"),
    ("on", "turn_on"),
    ("off", "turn_off"),
    ("running", "turn_on"),
    ("lit", "turn_on"),
    # clean: the scrub that makes it so ("table clean", "I want the plate spotless")
    ("wiped clean", "scrub"),
    ("wiped down", "scrub"),
    ("clean", "scrub"),
    ("spotless", "scrub"),
)
HELD = ("up in the air", "in the air", "up in the gripper", "in the gripper", "in the hand", "up", "held up", "raised")
# Participles that join an object to its goal in a wish ("I'd like the cup placed on the saucer").
PARTICIPLES: dict[str, str] = {
    "stacked": "stack",
    "piled": "stack",
    "pushed": "push",
    "slid": "push",
    "nudged": "push",
    "placed": "put",
    "put": "put",
    "set": "put",
    "sitting": "put",
    "resting": "put",
    "lying": "put",
    "standing": "put",
    "moved": "put",
    "dropped": "put",
    "stored": "put",
    "relocated": "put",
    "transferred": "put",
    # how a thing ends up seated on or in another ("the nut seated on the peg", "the lid fitted on the pot")
    "seated": "put",
    "sat": "put",
    "mounted": "put",
    "fitted": "put",
    "slotted": "put",
    "threaded": "put",
    "nestled": "put",
    "perched": "put",
    "parked": "put",
    "positioned": "put",
    "tucked": "put",
    "packed": "put",
    "lifted": "pick",
    "held": "pick",
    "raised": "pick",
    "picked up": "pick",
    "scrubbed": "scrub",
    "wiped": "scrub",
    "cleaned": "scrub",
    "poured": "pour",
    "emptied": "pour",
}
# Words that state a goal between the object and the place ("the apple belongs in the bowl").
COPULAS: tuple[str, ...] = (
    "should end up",
    "should be",
    "should go",
    "should sit",
    "should rest",
    "should stay",
    "must be",
    "must go",
    "needs to be",
    "needs to go",
    "has to be",
    "has to go",
    "ought to be",
    "is supposed to be",
    "belongs",
    "belong",
    "goes",
    "go",
    "ends up",
    "end up",
    # other verbs of ending up ("the juice finishes up in the basket", "winds up in")
    "finishes up",
    "finish up",
    "finishes",
    "winds up",
    "wind up",
    "is to be",
    "is to go",
    "to end up",
    "to be",
    "to go",
    "to sit",
    "needs",
)
# A modal and a verb of ending up: any pair states a goal ("ought to sit", "has to end up", "should land").
MODALS: tuple[str, ...] = (
    "should",
    "shall",
    "must",
    "ought to",
    "needs to",
    "need to",
    "has to",
    "have to",
    "is to",
    "are to",
)
MODALS += ("will", "is supposed to", "are supposed to", "is meant to", "are meant to", "wants to")
END_UP = ("be", "go", "sit", "rest", "stay", "end up", "stand", "lie", "land", "get", "wind up", "finish")
COPULAS += tuple(f"{m} {v}" for m in MODALS for v in END_UP)
# Verbs that say a container or a surface holds something ("the basket should contain the block").
HOLDS = ("contain", "contains", "hold", "holds", "have", "has", "get", "gets", "receive", "receives", "need", "needs")
