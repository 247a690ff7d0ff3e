"""The learned segmenter's category table: one entry per object category it predicts per pixel, each with a
name and a short description (what a text prompt is grounded against), plus the colour classes of its colour
head. Colours are kept apart from categories: a prompt's colour words filter instances by their predicted
colour, and its remaining words pick the category."""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Category:
    name: str
    description: str
    thing: bool = True  # False for stuff that is never a prompt's target (background, table, robot)


CATEGORIES: tuple[Category, ...] = (
    Category("background", "floor, walls and anything off the table", thing=False),
    Category("table", "the table top surface", thing=False),
    Category("robot", "the robot arm, its gripper and fingers", thing=False),
    Category("block", "small cube block, a wooden box-shaped cube"),
    Category("bowl", "round open ceramic bowl, a dish"),
    Category("plate", "flat round ceramic plate, a dinner dish"),
    Category("mug", "ceramic mug with a handle, a cylindrical cup"),
    Category("tray", "shallow square plastic tray"),
    Category("basket", "deep square woven wicker basket"),
    Category("sponge", "soft rectangular kitchen sponge"),
    Category("bottle", "tall cylindrical plastic bottle"),
    Category("peg", "square wooden peg, a short upright rod"),
    Category("nut", "square metal nut with a hole"),
    Category("brush", "scrubbing brush with a handle and bristles"),
    Category("zone", "flat square target area marked on the table, a region"),
    Category("cabinet", "wooden cabinet, a cupboard with a drawer"),
    Category("drawer", "the cabinet's sliding drawer"),
    Category("drawer handle", "metal handle on the cabinet drawer, a pull"),
    Category("stove", "electric stove, a cooktop with a burner"),
    Category("knob", "round control knob or dial on the stove"),
    Category("bead", "tiny round bead, a small ball"),
    Category("bar", "long straight rectangular wooden bar, a stick"),
    Category("carry tray", "long serving tray with a handle at each end"),
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
