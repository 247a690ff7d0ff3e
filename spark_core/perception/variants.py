"""Alternative text prompts for an object label (adaptive self-consistency), derived deterministically from
the label's words with a synonym table, and the word classes grounding needs to tell one kind of thing from
another. The planning layer may supply its own variants instead.

A variant never widens the label: it swaps a word for a synonym or adds an attribute, it never drops a word
("bbq sauce" -> "the sauce" would find the tomato sauce; "blue area" -> "the area" the green one) and never
swaps a noun for a wider one that also names another kind ("bowl" -> "dish" finds the plate)."""

from __future__ import annotations

SYNONYMS: dict[str, tuple[str, ...]] = {
    "block": ("cube", "wooden block"),
    "cube": ("block", "wooden cube"),
    "mug": ("cup", "coffee mug"),
    "cup": ("mug", "drinking cup"),
    "plate": ("dinner plate", "round plate"),
    "bowl": ("round bowl", "ceramic bowl"),
    "tray": ("plastic tray", "flat tray"),
    "basket": ("wicker basket", "woven basket"),
    "sponge": ("kitchen sponge", "scrubbing pad"),
    "bottle": ("plastic bottle", "flask"),
    "knob": ("dial", "control knob"),
    "handle": ("pull handle", "grip"),
    "drawer": ("cabinet drawer", "sliding drawer"),
    "stove": ("cooktop", "burner"),
    "cooktop": ("stove", "electric stove"),
    "hob": ("stove", "cooktop"),
    "burner": ("stove", "cooktop"),
    "cupboard": ("cabinet", "wooden cabinet"),
    "dish": ("plate", "round dish"),
    "zone": ("area", "target area"),
    "peg": ("rod", "stick"),
    "nut": ("metal nut", "brass nut"),
    "brush": ("scrub brush", "bristle brush"),
    "area": ("zone", "target area"),
    "bead": ("small ball", "marble"),
    "cabinet": ("cupboard", "wooden cabinet"),
}

# Kinds of things: each set holds words that name the same kind; a word of one set names something else than a
# word of another, unless it is in both (a wider word: "dish"): "butter" is no "milk", "ketchup" no "tomato
# sauce", however close a sentence encoder puts two groceries. Words in no set (containers such as "box" or
# "carton", generic nouns, rare names) stay open vocabulary: grounded by similarity alone.
KINDS: tuple[frozenset[str], ...] = tuple(
    frozenset(s.split())
    for s in (
        "block cube brick",
        "plate dish platter",
        "saucer",  # a small plate under a cup: a scene's dinner plate is no saucer
        "bowl dish basin",
        "ramekin dish",  # a ramekin is a small dish: "dish" may name it too
        # "bin" is a wider word: a basket or a tray
        "basket hamper bin",
        "crate",  # a slatted box: no basket (WordNet files both as distinct containers)
        "tray bin",
        "mug cup",
        "glass tumbler",
        "bottle flask",
        "jar",
        "sponge scrubber scourer pad",
        "brush",
        "towel cloth rag",
        "knob dial",
        "handle pull grip",
        "drawer layer",  # LIBERO's word for a cabinet's drawers ("the top layer of the wooden cabinet")
        "cabinet cupboard dresser",
        "stove cooktop burner hob cooker stovetop range",
        "oven",
        "microwave",
        "fridge refrigerator",
        "sink basin",
        "toaster",
        "kettle",
        "pan skillet",
        "pot saucepan",
        "lid",
        "spoon",
        "fork",
        "knife",
        "spatula",
        "peg rod post pole pin",
        "nut",
        "bolt",
        "screw",
        "hammer mallet",
        # other hand tools: each its own kind (a "wrench" is no hammer, however near an encoder puts them)
        "wrench spanner",
        "screwdriver",
        "pliers",
        "chisel",
        "wool",  # steel wool (rules/names.py says "steel wool pad" so): no sponge
        "bead marble ball",
        "area zone region target patch spot",
        "rack holder stand",  # "the wine holder", "the bottle stand": a rack (a holder of nothing in particular)
        "shelf",
        "vase",
        "book",
        "lamp",
        "door",
        # a row names one product (its spellings, regional names, abbreviations), never a substitute for it:
        # margarine stands in for butter and marmalade for jam, and neither is the other
        "butter",
        "margarine",
        "milk",
        "ketchup catsup",
        "cheese",
        "soup",
        "pudding",
        "juice oj",
        "dressing vinaigrette",
        "sauce",
        "cookie biscuit",
        "cereal",
        "bread loaf",
        "bag sack",  # a bag holds groceries: no basket, box or bottle is one
        "apple",
        "banana",
        "lemon",
        "wine vino",
        "egg",
        # things a scene may lack that an encoder puts near what it holds ("mustard" next to the ketchup, "ball"
        # next to a block): naming them is naming another kind
        "ball sphere",
        "mustard",
        "mayonnaise mayo",
        "soda cola",
        "beer",
        "teapot",
        "pen",
        "pencil",
        "cylinder",
        "pyramid",
        "dirt mess stain spill grime smudge dust muck gunk crud filth",
        "yogurt yoghurt",
        "jam jelly",
        "marmalade",
        "honey",
        "pasta noodles",
        "rice",
        "bucket pail",
        "blender",
        "napkin serviette",
    )
)
# Kinds that are food or drink: as a modifier they say what a thing holds or is made of ("beer bottle", "wine
# rack"), so they must be the object's own; another kind as a modifier may say what a thing is for ("bottle rack").
CONSUMABLES = frozenset(
    ["butter", "milk", "ketchup", "cheese", "soup", "pudding", "juice", "dressing", "sauce", "cookie", "biscuit"]
    + ["cereal", "bread", "apple", "banana", "lemon", "wine", "egg", "mustard", "mayonnaise", "mayo", "soda", "cola"]
    + ["beer", "yogurt", "yoghurt", "jam", "jelly", "marmalade", "honey", "pasta", "noodles", "rice", "margarine"]
)
# Other spellings and abbreviations of a word in an object's name: read as that word.
SPELLINGS: dict[str, str] = {"barbecue": "bbq", "barbeque": "bbq", "yoghurt": "yogurt"}
# word -> every word of a kind it may name ("dish": a plate or a bowl)
KIND_OF: dict[str, frozenset[str]] = {w: frozenset().union(*(k for k in KINDS if w in k)) for s in KINDS for w in s}
# Attribute words: a mention may add them without naming another kind; colours are in colors.py.
SHAPES = frozenset(
    ["square", "round", "circular", "rectangular", "hexagonal", "triangular", "cylindrical", "oval", "spherical"]
    # shape words said as nouns before a noun ("hex nut", "triangle peg"): a shape claim all the same
    + ["hex", "hexagon", "triangle", "octagonal", "octagon", "pentagonal", "pentagon", "star", "oblong"]
)
MATERIALS = frozenset(
    ["wooden", "wood", "metal", "metallic", "plastic", "ceramic", "glass", "brass", "steel", "wicker", "woven"]
)
SIZES = frozenset(
    ["small", "big", "large", "tiny", "little", "tall", "short", "long", "wide", "narrow", "shallow", "deep", "flat"]
)


# Nouns naming a part of a thing or what a product comes in: "the stove knob", "the ketchup bottle", "the cookie
# box" name the stove, the ketchup and the cookies through a modifier; any other head noun must itself name the object.
PARTS = frozenset(
    ["knob", "dial", "handle", "grip", "pull", "lid", "door", "drawer", "button", "switch", "top", "front", "back"]
    + ["side", "edge", "rim", "base", "bottom", "surface", "layer", "tier", "shelf", "burner", "cover", "cap"]
)
PACKAGING = frozenset(
    ["box", "bottle", "carton", "jar", "can", "tin", "pack", "packet", "package", "container", "tub", "bag", "case"]
    + ["pouch", "packaging", "stick", "bar", "slice", "loaf", "wedge", "tube", "roll", "sachet", "bunch"]
)
# Nouns that name no kind at all ("the red thing", "that item"): they add nothing against any object.
GENERIC = frozenset(["thing", "object", "item", "stuff", "piece", "one", "receptacle", "vessel", "product", "goods"])
# Words that may end a mention without being its noun ("the bowl inside", "the cup upright"): no noun check on them.
NOT_NOUNS = frozenset(
    ["inside", "outside", "there", "here", "upright", "away", "up", "down", "off", "over", "too", "please", "now"]
    + ["again", "instead", "then", "only", "also", "itself", "it", "them", "both", "either", "all"]
    + ["out", "in", "aside", "along", "around", "together", "apart", "forward", "backward", "closed", "open"]
)


def prompt_variants(label: str, k: int = 3) -> list[str]:
    """`k` alternative prompts for `label` (never the label itself), e.g. red block -> red cube, red wooden block.
    Never the bare noun ("the area"): a variant that widens the label finds another object (the green area for
    "blue area"). Never a narrower noun either (`_narrows`): "dish" -> "plate" would pick the plate of a plate and a
    bowl the label names alike, where the label itself is ambiguous."""
    words = label.split()
    out: list[str] = []
    for i in range(len(words) - 1, -1, -1):
        for syn in SYNONYMS.get(words[i], ()):
            if _narrows(words[i], syn):
                continue
            cand = " ".join(words[:i] + [syn] + words[i + 1 :])
            if cand != label and cand not in out:
                out.append(cand)
    return out[:k]


def _narrows(word: str, synonym: str) -> bool:
    """`synonym` names only some of the kinds `word` names ("dish": a plate, a bowl or a ramekin; "plate": a plate)."""
    wide, narrow = KIND_OF.get(word), KIND_OF.get(synonym)
    return wide is not None and narrow is not None and narrow < wide
