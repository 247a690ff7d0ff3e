"""The learned segmenter's category table: one entry per object category it predicts per pixel, each with a
name and a short description (what a text prompt is grounded against), plus the colour classes of its colour
head. Colours are kept apart from categories: a prompt's colour words filter instances by their predicted
colour, and its remaining words pick the category."""

from __future__ import annotations

import re
from dataclasses import dataclass


@dataclass(frozen=True)
class Category:
    name: str
    description: str
    thing: bool = True  # False for stuff that is never a prompt's target (background, table, robot)
    part_of: tuple[str, ...] = ()  # a part is only ever seen on one of these (instances elsewhere are dropped)
    # widest an object of this kind is (m, world xy): pieces a depth edge cut apart (a bowl's rim and bottom) are
    # joined up to it; 0 for kinds seen as one surface
    max_extent_m: float = 0.0
    # a part standing proud of its parent's face by about this much (m): mask pixels further than this behind the
    # part's nearest pixels are the face around it (a handle's mask found at half resolution spills onto it)
    proud_m: float = 0.0
    # tallest an object of this kind stands (m, world z): mask pixels further below its seen top are what it
    # stands on (a bowl on a cookie box or a ramekin; the per-pixel network paints the support's top as bowl);
    # 0 for kinds whose height varies too much to say
    max_height_m: float = 0.0
    # smallest an object of this kind measures along its longest side (m, world): a smaller piece standing on
    # another object is part of that object (learned/pieces.py); 0 for kinds that can be any size
    min_extent_m: float = 0.0


CATEGORIES: tuple[Category, ...] = (
    Category("background", "floor, walls and anything off the table", thing=False),
    Category("table", "the table top surface", thing=False),
    Category("robot", "the robot arm, its gripper and fingers", thing=False),
    Category("block", "small cube block, a wooden box-shaped cube"),
    Category("bowl", "round open ceramic bowl, a dish", max_extent_m=0.18, max_height_m=0.06),
    Category("plate", "flat round ceramic plate, a dinner dish", max_height_m=0.03),
    Category("mug", "ceramic mug with a handle, a cylindrical cup", max_extent_m=0.15),
    Category("tray", "shallow square plastic tray", max_extent_m=0.32),
    Category("basket", "deep square woven wicker basket", max_extent_m=0.30),
    Category("sponge", "soft rectangular kitchen sponge"),
    Category("bottle", "tall cylindrical plastic bottle"),
    Category("peg", "square wooden peg, a short upright rod"),
    Category("nut", "square metal nut with a hole"),
    # a brush is 14 cm long: a few centimetres of "brush" on a plate is a piece of the plate (scrub_plate: its rim)
    Category("brush", "scrubbing brush with a handle and bristles", min_extent_m=0.08),
    Category("zone", "flat square target area marked on the table, a region"),
    Category("cabinet", "wooden cabinet, a cupboard with a drawer", max_extent_m=0.40),
    Category("drawer", "the cabinet's sliding drawer", part_of=("cabinet",), max_extent_m=0.35),
    Category(
        "drawer handle", "metal handle on the cabinet drawer, a pull", part_of=("drawer", "cabinet"), proud_m=0.02
    ),
    Category("stove", "electric stove, a cooktop with a burner"),
    Category("knob", "round control knob or dial on the stove", part_of=("stove",)),
    Category("bead", "tiny round bead, a small ball"),
    Category("bar", "long straight rectangular wooden bar, a stick"),
    Category("carry tray", "long serving tray with a handle at each end"),
    # LIBERO objects (appended: the indices above are those of earlier weights, see train.expand_categories)
    Category("wine bottle", "dark glass wine bottle with a long neck", min_extent_m=0.10),
    Category("wine rack", "metal wine rack, a stand that holds bottles", max_extent_m=0.40),
    Category("cream cheese", "small rectangular box of cream cheese"),
    Category("ramekin", "small round white porcelain ramekin with a glazed rim", max_extent_m=0.15, max_height_m=0.06),
    Category("cookie box", "rectangular cardboard box of cookies"),
    Category("alphabet soup", "can of alphabet soup, a food tin"),
    Category("bbq sauce", "bottle of barbecue sauce"),
    Category("butter", "small box of butter"),  # LIBERO's butter: a printed box, not a gabled carton
    Category("chocolate pudding", "small box of chocolate pudding"),
    Category("ketchup", "squeeze bottle of tomato ketchup"),
    Category("milk", "carton of milk"),
    Category("orange juice", "carton of orange juice"),
    Category("salad dressing", "bottle of salad dressing"),
    Category("tomato sauce", "can of tomato sauce"),
    # CaP-Bench objects without an earlier category (appended for the same reason)
    Category("pot", "metal cooking pot with a handle on each side", max_extent_m=0.45),
    Category("hammer", "hammer, a wooden handle with a metal head"),
    Category("dirt", "dirt, brown stains or marks on the table to wipe off"),
)
CATEGORY_INDEX: dict[str, int] = {c.name: i for i, c in enumerate(CATEGORIES)}
BACKGROUND, TABLE, ROBOT = (CATEGORY_INDEX[n] for n in ("background", "table", "robot"))

# Object kinds of the scene builder (spark_core.sim.objects.KINDS) and part suffixes -> category names.
KIND_CATEGORY: dict[str, str] = {
    "ball": "bead",
    "carry_tray": "carry tray",
    "knob": "knob",
    "drawer": "drawer",
    "drawer handle": "drawer handle",
}

# LIBERO object names (the adapter's labels without a trailing instance number) -> category names; a drawer's
# parts are "<fixture> <level> drawer" and "... drawer handle" (sim/libero_envs.py).
LIBERO_CATEGORY: dict[str, str] = {
    "floor": "background",
    "table": "table",
    "main table": "table",
    "akita black bowl": "bowl",
    "white bowl": "bowl",
    "plate": "plate",
    "basket": "basket",
    "wooden cabinet": "cabinet",
    "white cabinet": "cabinet",
    "flat stove": "stove",
    "wine bottle": "wine bottle",
    "wine rack": "wine rack",
    "cream cheese": "cream cheese",
    "glazed rim porcelain ramekin": "ramekin",
    "cookies": "cookie box",
    "alphabet soup": "alphabet soup",
    "bbq sauce": "bbq sauce",
    "butter": "butter",
    "chocolate pudding": "chocolate pudding",
    "ketchup": "ketchup",
    "milk": "milk",
    "orange juice": "orange juice",
    "salad dressing": "salad dressing",
    "tomato sauce": "tomato sauce",
}


def libero_description(name: str) -> str:
    """What a LIBERO object (the adapter's label without its instance number) looks like and comes in ("carton of
    milk"), by its category; "" for a name of no category here."""
    category = LIBERO_CATEGORY.get(name)
    return CATEGORIES[CATEGORY_INDEX[category]].description if category else ""


# Colour classes of the colour head: index 0 = no colour (not an object); the rest are spark_core.perception
# .colors.BASE_COLOURS names ("wood" renders as brown).
COLOURS: tuple[str, ...] = (
    "none",
    "red",
    "green",
    "blue",
    "yellow",
    "white",
    "black",
    "brown",
    "grey",
    "orange",
    "purple",
    "pink",
)
COLOUR_INDEX: dict[str, int] = {c: i for i, c in enumerate(COLOURS)}


def category_of_kind(kind: str) -> int:
    """Category index of a scene-builder object kind or part suffix; a clear error for one it has no class for."""
    name = KIND_CATEGORY.get(kind, kind)
    if name not in CATEGORY_INDEX:
        raise KeyError(f"no learned category for object kind {kind!r}; categories: {', '.join(CATEGORY_INDEX)}")
    return CATEGORY_INDEX[name]


def category_of_libero(label: str) -> int:
    """Category index of a LIBERO scene label ("akita black bowl 2", "wooden cabinet top drawer handle"); a clear
    error for an object it has no class for."""
    base = re.sub(r" \d+$", "", label)
    for part in ("drawer handle", "drawer"):
        if base.endswith(" " + part):
            return CATEGORY_INDEX[part]
    if base not in LIBERO_CATEGORY:
        raise KeyError(f"no learned category for LIBERO object {label!r}; known: {', '.join(LIBERO_CATEGORY)}")
    return CATEGORY_INDEX[LIBERO_CATEGORY[base]]
