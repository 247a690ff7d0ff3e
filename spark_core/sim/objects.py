"""The object library: every object is built from MuJoCo primitives and carries a label, a short description
(colour, shape, material) and a category, which is what perception grounds text prompts against."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

import mujoco
import numpy as np

BOX, CYL, SPHERE, CAPSULE = (
    mujoco.mjtGeom.mjGEOM_BOX,
    mujoco.mjtGeom.mjGEOM_CYLINDER,
    mujoco.mjtGeom.mjGEOM_SPHERE,
    mujoco.mjtGeom.mjGEOM_CAPSULE,
)
COLORS = {
    "red": [0.85, 0.12, 0.1, 1],
    "green": [0.15, 0.65, 0.2, 1],
    "blue": [0.12, 0.3, 0.85, 1],
    "yellow": [0.95, 0.8, 0.1, 1],
    "white": [0.93, 0.93, 0.9, 1],
    "black": [0.08, 0.08, 0.08, 1],
    "brown": [0.5, 0.33, 0.18, 1],
    "grey": [0.55, 0.55, 0.58, 1],
    "orange": [0.95, 0.5, 0.1, 1],
    "purple": [0.5, 0.2, 0.7, 1],
    "pink": [0.95, 0.55, 0.7, 1],
    "wood": [0.72, 0.55, 0.35, 1],
}


@dataclass(frozen=True)
class ObjectSpec:
    """A kind of object. `footprint_m` is the radius it needs on the table; `height_m` its full height.

    Parts are labelled sub-bodies (a drawer's handle, a stove's knob) that perception can also resolve.
    """

    kind: str
    category: str  # block | container | tableware | fixture | tool | food
    description: str  # colour, shape, material: what a text prompt is matched against
    footprint_m: float
    height_m: float
    movable: bool
    build: Callable[[mujoco.MjsBody, list], None]
    parts: dict[str, str] = field(default_factory=dict)  # part label suffix -> description
    grasp_width_m: float | None = None


def _geom(body, type_, size, pos=(0, 0, 0), rgba=None, mass=None, **kw):
    g = body.add_geom(type=type_, size=list(size) + [0] * (3 - len(size)), pos=list(pos), **kw)
    if rgba is not None:
        g.rgba = rgba
    if mass is not None:
        g.mass = mass
    g.friction = [1.0, 0.01, 0.001]
    return g


def block(color: str, half: float = 0.02) -> ObjectSpec:
    def build(body, rgba):
        _geom(body, BOX, [half, half, half], (0, 0, half), rgba, mass=0.08)

    return ObjectSpec(
        "block", "block", f"small {color} wooden cube block", half * 1.6, 2 * half, True, build, grasp_width_m=2 * half
    )


def _ring(body, radius, wall_h, n, thick, rgba, z0, mass):
    for k in range(n):
        a = 2 * np.pi * k / n
        half_len = radius * np.tan(np.pi / n) + thick / 2
        g = _geom(
            body,
            BOX,
            [thick / 2, half_len, wall_h / 2],
            (radius * np.cos(a), radius * np.sin(a), z0 + wall_h / 2),
            rgba,
            mass=mass / n,
        )
        g.quat = [np.cos(a / 2), 0, 0, np.sin(a / 2)]


def _visual_only(g):
    g.contype = 0
    g.conaffinity = 0
    g.group = 1
    return g


def _collision_only(g):
    g.group = 3  # hidden from cameras and the viewer
    g.rgba = [0, 0, 0, 0]
    return g


def bowl(color: str) -> ObjectSpec:
    def build(body, rgba):
        _visual_only(_geom(body, CYL, [0.066, 0.005], (0, 0, 0.005), rgba, mass=0.001))
        _collision_only(_geom(body, BOX, [0.05, 0.05, 0.005], (0, 0, 0.005), None, mass=0.15))  # see plate()
        _ring(body, 0.07, 0.05, 12, 0.008, rgba, 0.0, 0.2)

    return ObjectSpec("bowl", "container", f"{color} ceramic bowl, round and open", 0.085, 0.05, True, build)


def plate(color: str) -> ObjectSpec:
    # A flat cylinder sinks into the table (single-point cylinder/box contact): collide as a square slab instead.
    def build(body, rgba):
        _visual_only(_geom(body, CYL, [0.09, 0.008], (0, 0, 0.008), rgba, mass=0.0001))
        _collision_only(_geom(body, BOX, [0.075, 0.075, 0.008], (0, 0, 0.008), None, mass=1.2))

    return ObjectSpec("plate", "tableware", f"flat round {color} ceramic plate", 0.095, 0.016, True, build)


def mug(color: str) -> ObjectSpec:
    def build(body, rgba):
        _visual_only(_geom(body, CYL, [0.03, 0.004], (0, 0, 0.004), rgba, mass=0.001))
        _collision_only(_geom(body, BOX, [0.024, 0.024, 0.004], (0, 0, 0.004), None, mass=0.06))  # see plate()
        _ring(body, 0.032, 0.09, 10, 0.006, rgba, 0.0, 0.12)
        _geom(body, BOX, [0.008, 0.006, 0.03], (0.05, 0.0, 0.05), rgba, mass=0.01)  # the handle, facing +x

    return ObjectSpec(
        "mug",
        "container",
        f"{color} ceramic mug with a handle, cylindrical cup",
        0.06,
        0.09,
        True,
        build,
        grasp_width_m=0.07,
    )


def _open_box(half: float, wall_half_t: float, wall_half_h: float, wall_mass: float):
    """Builder of a square open container: a 4 mm floor and four walls (half sizes in metres)."""

    def build(body, rgba):
        _geom(body, BOX, [half, half, 0.004], (0, 0, 0.004), rgba, mass=0.3)
        c = half - 0.002  # wall centre line, 2 mm inside the floor edge
        for sx, sy, hx, hy in (
            (1, 0, wall_half_t, half),
            (-1, 0, wall_half_t, half),
            (0, 1, half, wall_half_t),
            (0, -1, half, wall_half_t),
        ):
            _geom(body, BOX, [hx, hy, wall_half_h], (sx * c, sy * c, 0.004 + wall_half_h), rgba, mass=wall_mass)

    return build


def tray(color: str) -> ObjectSpec:
    return ObjectSpec(
        "tray",
        "container",
        f"shallow square {color} plastic tray",
        0.13,
        0.028,
        False,
        _open_box(0.09, 0.004, 0.012, 0.05),
    )


def basket(color: str) -> ObjectSpec:
    return ObjectSpec(
        "basket",
        "container",
        f"{color} woven wicker basket, square and deep",
        0.125,
        0.074,
        False,
        _open_box(0.08, 0.005, 0.035, 0.08),
    )


def sponge(color: str) -> ObjectSpec:
    def build(body, rgba):
        g = _geom(body, BOX, [0.035, 0.022, 0.015], (0, 0, 0.015), rgba, mass=0.03)
        g.friction = [0.4, 0.005, 0.0001]  # slides over what it scrubs instead of dragging it along

    return ObjectSpec(
        "sponge", "tool", f"soft rectangular {color} kitchen sponge", 0.045, 0.03, True, build, grasp_width_m=0.044
    )


def bottle(color: str) -> ObjectSpec:
    def build(body, rgba):
        _geom(body, CYL, [0.025, 0.07], (0, 0, 0.07), rgba, mass=0.15)
        _geom(body, CYL, [0.012, 0.02], (0, 0, 0.16), rgba, mass=0.01)

    return ObjectSpec(
        "bottle", "container", f"tall {color} plastic bottle, cylindrical", 0.04, 0.18, True, build, grasp_width_m=0.05
    )


def peg(color: str) -> ObjectSpec:
    def build(body, rgba):
        _geom(body, BOX, [0.012, 0.012, 0.05], (0, 0, 0.05), rgba, mass=0.05)

    return ObjectSpec(
        "peg", "tool", f"{color} square wooden peg, a short rod", 0.03, 0.1, True, build, grasp_width_m=0.024
    )


def nut(color: str) -> ObjectSpec:
    def build(body, rgba):
        for sx, sy, hx, hy in (
            (1, 0, 0.008, 0.035),
            (-1, 0, 0.008, 0.035),
            (0, 1, 0.035, 0.008),
            (0, -1, 0.035, 0.008),
        ):
            _geom(body, BOX, [hx, hy, 0.01], (sx * 0.027, sy * 0.027, 0.01), rgba, mass=0.02)

    return ObjectSpec(
        "nut", "tool", f"{color} square metal nut with a hole", 0.05, 0.02, True, build, grasp_width_m=0.016
    )


def brush(color: str) -> ObjectSpec:
    def build(body, rgba):
        _geom(body, BOX, [0.05, 0.012, 0.012], (0, 0, 0.012), rgba, mass=0.04)
        _geom(body, BOX, [0.02, 0.02, 0.008], (0.06, 0, 0.008), COLORS["black"], mass=0.02)

    return ObjectSpec(
        "brush",
        "tool",
        f"{color} scrubbing brush with a handle and black bristles",
        0.07,
        0.024,
        True,
        build,
        grasp_width_m=0.024,
    )


def bar(color: str) -> ObjectSpec:
    """A long bar (26 cm): long enough for two hands to hold it at once (hand-overs)."""

    def build(body, rgba):
        _geom(body, BOX, [0.13, 0.0125, 0.016], (0, 0, 0.016), rgba, mass=0.12)

    return ObjectSpec(
        "bar",
        "tool",
        f"long {color} wooden bar, a straight rectangular stick",
        0.14,
        0.032,
        True,
        build,
        grasp_width_m=0.025,
    )


def carry_tray(color: str) -> ObjectSpec:
    """A 34 cm tray with an upright handle at each end (along its x axis), to be lifted with two hands."""

    def build(body, rgba):
        _geom(body, BOX, [0.15, 0.08, 0.004], (0, 0, 0.004), rgba, mass=0.25)
        for sy in (-1, 1):  # low rims along the long sides
            _geom(body, BOX, [0.15, 0.004, 0.012], (0, sy * 0.076, 0.016), rgba, mass=0.03)
        for sx in (-1, 1):  # the handles: posts the fingers close across (2.4 cm)
            _geom(body, BOX, [0.012, 0.03, 0.03], (sx * 0.162, 0, 0.03), rgba, mass=0.04)

    return ObjectSpec(
        "carry_tray",
        "container",
        f"long {color} serving tray with a handle at each end",
        0.19,
        0.06,
        True,
        build,
        grasp_width_m=0.024,
    )


def target_zone(color: str) -> ObjectSpec:
    def build(body, rgba):
        g = _geom(body, BOX, [0.07, 0.07, 0.0005], (0, 0, 0.0005), [rgba[0], rgba[1], rgba[2], 0.5])
        g.contype = 0
        g.conaffinity = 0

    return ObjectSpec(
        "zone", "fixture", f"flat {color} square target area marked on the table", 0.1, 0.001, False, build
    )


CABINET_DEPTH, DRAWER_TRAVEL = 0.2, 0.2


def cabinet(color: str) -> ObjectSpec:
    """Cabinet whose drawer opens toward the robot (-x of the cabinet frame): slide joint `drawer`."""

    def build(body, rgba):
        w, d, h = 0.14, CABINET_DEPTH / 2, 0.075  # half sizes
        for pos, size in (
            ((0, -w, h), (d, 0.01, h)),
            ((0, w, h), (d, 0.01, h)),
            ((d, 0, h), (0.01, w, h)),
            ((0, 0, 2 * h + 0.01), (d, w + 0.01, 0.01)),
            ((0, 0, 0.005), (d, w, 0.005)),
        ):
            _geom(body, BOX, size, pos, rgba, mass=1.0)
        drawer = body.add_body(name=body.name + "/drawer", pos=[0, 0, 0.02])
        drawer.add_joint(
            name=body.name + "/drawer_slide",
            type=mujoco.mjtJoint.mjJNT_SLIDE,
            axis=[-1, 0, 0],
            range=[0.0, DRAWER_TRAVEL],
            damping=8.0,
            frictionloss=0.5,
        )
        inner = COLORS["wood"]
        _geom(drawer, BOX, [d - 0.01, w - 0.015, 0.005], (0, 0, 0.005), inner, mass=0.2)
        for pos, size in (
            ((0, -(w - 0.02), 0.04), (d - 0.01, 0.005, 0.035)),
            ((0, w - 0.02, 0.04), (d - 0.01, 0.005, 0.035)),
            ((d - 0.02, 0, 0.04), (0.005, w - 0.02, 0.035)),
            ((-(d - 0.005), 0, 0.05), (0.008, w - 0.016, 0.045)),
        ):
            _geom(drawer, BOX, size, pos, inner, mass=0.1)
        handle = drawer.add_body(name=body.name + "/handle", pos=[-(d + 0.03), 0, 0.07])
        # A vertical pull: a horizontal-approach grasp closes the fingers sideways around it, keeping the wide
        # hand clear of the table.
        _geom(handle, BOX, [0.008, 0.008, 0.035], (0, 0, 0), COLORS["grey"], mass=0.02)
        for sz in (-1, 1):
            _geom(handle, BOX, [0.016, 0.006, 0.005], (0.018, 0, sz * 0.03), COLORS["grey"], mass=0.005)

    return ObjectSpec(
        "cabinet",
        "fixture",
        f"{color} wooden cabinet with one drawer",
        0.2,
        0.17,
        False,
        build,
        parts={"drawer": "the cabinet's sliding drawer", "drawer handle": "metal handle on the cabinet drawer"},
    )


def stove(color: str) -> ObjectSpec:
    """Stove with a burner plate and a front knob on a hinge joint `knob` (turn it to switch the stove on)."""

    def build(body, rgba):
        _geom(body, BOX, [0.1, 0.12, 0.02], (0, 0, 0.02), rgba, mass=2.0)
        burner = _geom(body, CYL, [0.06, 0.003], (0.02, 0, 0.043), COLORS["black"])
        burner.contype = 1
        knob = body.add_body(name=body.name + "/knob", pos=[-0.085, 0.0, 0.055])
        knob.add_joint(
            name=body.name + "/knob_hinge",
            type=mujoco.mjtJoint.mjJNT_HINGE,
            axis=[0, 0, 1],
            range=[-3.2, 3.2],
            damping=0.3,
            frictionloss=0.15,
        )  # a detent-like friction: it stays where turned
        _geom(knob, CYL, [0.02, 0.013], (0, 0, 0), COLORS["white"], mass=0.02)
        _geom(knob, BOX, [0.018, 0.005, 0.012], (0, 0, 0.02), COLORS["white"], mass=0.005)

    return ObjectSpec(
        "stove",
        "fixture",
        f"{color} electric stove (cooktop) with a black burner",
        0.16,
        0.043,
        False,
        build,
        parts={"knob": "white round control knob on the stove"},
    )


def ball(color: str, radius: float = 0.007) -> ObjectSpec:
    def build(body, rgba):
        _geom(body, SPHERE, [radius], (0, 0, radius), rgba, mass=0.002)

    return ObjectSpec("ball", "food", f"tiny {color} bead", radius, 2 * radius, True, build)


def fork(color: str) -> ObjectSpec:
    """A 13 cm table fork lying flat: a handle (the middle of the fork, where a hand takes it) and a wider head
    with four tines."""

    def build(body, rgba):
        _geom(body, BOX, [0.04, 0.006, 0.007], (-0.025, 0, 0.007), rgba, mass=0.03)
        _geom(body, BOX, [0.012, 0.013, 0.005], (0.027, 0, 0.005), rgba, mass=0.01)
        for k in range(4):  # tines
            _geom(body, BOX, [0.013, 0.002, 0.004], (0.052, -0.0105 + 0.007 * k, 0.004), rgba, mass=0.002)

    return ObjectSpec(
        "fork", "tableware", f"{color} metal table fork with four tines", 0.07, 0.014, True, build, grasp_width_m=0.012
    )


def knife(color: str) -> ObjectSpec:
    """A 13 cm table knife lying flat: a thick handle (the middle of the knife, where a hand takes it) and a thin
    blade."""

    def build(body, rgba):
        _geom(body, BOX, [0.04, 0.007, 0.007], (-0.025, 0, 0.007), rgba, mass=0.03)
        _geom(body, BOX, [0.025, 0.009, 0.003], (0.04, 0, 0.003), rgba, mass=0.01)

    return ObjectSpec(
        "knife",
        "tableware",
        f"{color} metal table knife with a flat blade",
        0.07,
        0.014,
        True,
        build,
        grasp_width_m=0.014,
    )


KINDS: dict[str, Callable[[str], ObjectSpec]] = {
    "block": block,
    "bowl": bowl,
    "plate": plate,
    "mug": mug,
    "tray": tray,
    "basket": basket,
    "sponge": sponge,
    "bottle": bottle,
    "peg": peg,
    "nut": nut,
    "brush": brush,
    "zone": target_zone,
    "cabinet": cabinet,
    "stove": stove,
    "ball": ball,
    "bar": bar,
    "carry_tray": carry_tray,
    "fork": fork,
    "knife": knife,
}
