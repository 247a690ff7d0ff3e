"""Words the rules planner understands: verbs (with synonyms), prepositions, directions."""

from __future__ import annotations

# action -> surface forms, longest first within each list is not required (matching picks the longest)
VERBS: dict[str, tuple[str, ...]] = {
    "pick": ("pick up", "pick", "lift up", "lift", "grab", "grasp", "take", "raise", "hold up", "get"),
    "put": ("put", "place", "set", "move", "drop", "transfer", "bring", "carry", "relocate", "store", "stick", "lay"),
    "stack": ("stack", "pile"),
    "push": ("push", "shove", "nudge", "slide"),
    "open": ("open", "pull open", "slide open"),
    "close": ("close", "shut", "push closed", "push shut"),
    "turn_on": ("turn on", "switch on", "ignite", "start", "light"),
    "turn_off": ("turn off", "switch off"),
    "pour": ("pour", "empty", "tip", "dump"),
    "scrub": ("scrub", "wipe", "clean", "scour", "wash"),
    "sort": ("sort",),
}
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
DETERMINERS = ("the", "a", "an", "this", "that", "these", "those", "some", "all")
PRONOUNS = ("it", "them", "there")
# Words that carry no action. ("then" is not one: it separates clauses.)
FILLERS = (
    "please",
    "carefully",
    "gently",
    "slowly",
    "now",
    "also",
    "first",
    "finally",
    "next",
    "can you",
    "could you",
    "would you",
    "i want you to",
    "go ahead and",
    "robot,",
)
