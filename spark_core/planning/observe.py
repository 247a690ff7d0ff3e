"""What the planner gets to see: perception run on the phrases an instruction mentions.

The planner never receives a ground-truth object list: each noun phrase of the instruction (and the parts an
action needs, e.g. a drawer's handle) is handed to perception, and only what perception finds is in the view.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from ..perception import Keypoint, LabelNotFound
from ..perception.resolver_protocol import Resolver
from ..perception.summary import summarise
from .protocol import SceneView
from .rules.chunks import noun_chunks
from .rules.descriptions import descriptions
from .rules.discourse import restructured
from .rules.lexicon import CLEANERS, CONTAINERS, CONTENTS
from .rules.mentions import clause_mentions, read_past, stray_nouns
from .rules.parse import Clause, ParseError, is_pronoun, parse_instruction
from .rules.qualify import bare_rank
from .rules.reader import phrases as order_free_phrases
from .rules.reader import readings as order_free_readings
from .rules.remarks import trailing_remarks
from .rules.spelling import corrected

PART_OF_ACTION = {"open": "handle", "close": "handle", "turn_on": "knob", "turn_off": "knob"}


def phrases_for(instruction: str, remarks: bool = True) -> list[str]:
    """Noun phrases to look for: objects, targets, tools, sources, plus the part an action grips; with `remarks`,
    also those of the instruction read without the trailing clauses that may only remark (rules/remarks.py: the
    planner reads it so when the whole refuses)."""
    # what an order-free reading needs (rules/reader.py): the planner's fallback when the rule parse refuses; with
    # the part an action of it grips ("open the drawer that is neither the top one nor the middle one")
    after = order_free_phrases(instruction)
    after += [p for reading in order_free_readings(instruction) for p in _gripped(reading) if p not in after]
    try:
        clauses = parse_instruction(instruction)
    except ParseError:
        # no reading gives anything to look for: the sentence's noun phrases, for the learned reader to rank goals over
        return _with_described(instruction, after or noun_chunks(instruction), remarks)
    out: dict[str, None] = {}
    for c in clauses:
        for p in (c.obj, c.target, c.tool, c.source):
            if p and not is_pronoun(p):
                out.setdefault(p, None)
        if c.to_arm and c.obj:  # handed from arm to arm: gripped by its handle, if it has one
            out.setdefault(f"{c.obj} handle", None)
        if c.action == "put" and c.relation == "in" and c.target and "drawer" in c.target.split():
            # into a drawer: the planner opens it first when no step does, by its handle
            out.setdefault(f"{c.target} handle", None)
            out.setdefault("drawer handle", None)
        if c.action == "pour" and c.source and c.source.split()[-1] in CONTENTS:
            # "the beads should end up in the bowl": poured from a container perception finds (planner.py)
            for holder in CONTAINERS:
                out.setdefault(holder, None)
        if c.action == "scrub" and not c.tool:  # "plate clean": scrubbed with the cleaning tool found (planner.py)
            for cleaner in CLEANERS:
                out.setdefault(cleaner, None)
        for p in _gripped([c]):
            out.setdefault(p, None)
    # what the phrases are located by, what the parser read past, and any noun no phrase holds: each must be in the
    # scene (rules/mentions.py)
    for p in [*clause_mentions(clauses), *read_past(instruction, clauses), *stray_nouns(instruction, clauses)]:
        out.setdefault(p, None)
    for p in after:
        out.setdefault(p, None)
    for p in list(out):  # "the second plate": how many plates there are (planner.py refuses it when one)
        kind = bare_rank(p)
        if kind:
            out.setdefault(kind, None)
    for kept, _ in trailing_remarks(instruction, [])[:2] if remarks else []:
        for p in phrases_for(kept, remarks=False):
            out.setdefault(p, None)
    return _with_described(instruction, list(out), remarks)


def _with_described(instruction: str, found: list[str], remarks: bool) -> list[str]:
    """`found`, and with `remarks` the phrases of the request read without the sentences that only describe
    (rules/descriptions.py: the planner reads it so when the whole refuses)."""
    kept, described = descriptions(instruction, None) if remarks else (instruction, [])
    extra = phrases_for(restructured(kept)) if described else []
    return list(dict.fromkeys([*found, *extra]))


def _gripped(clauses: list[Clause]) -> list[str]:
    """The parts the clauses' actions grip: a drawer's handle, a stove's knob."""
    out: dict[str, None] = {}
    for c in clauses:
        part = PART_OF_ACTION.get(c.action)
        if part and c.obj:
            out.setdefault(f"{c.obj} {part}", None)
            if "drawer" in c.obj:
                out.setdefault(f"drawer {part}", None)
            elif part == "knob" and len(c.obj.split()) > 1:  # "the grey stove": its knob is not grey
                out.setdefault(f"{c.obj.split()[-1]} {part}", None)
    return list(out)


def observe(instruction: str, resolver: Resolver, extra: Sequence[str] = ()) -> SceneView:
    keypoints: dict[str, Keypoint] = {}
    unresolved: dict[str, str] = {}
    listing = getattr(resolver, "inventory", None)
    inventory = tuple(listing()) if listing else ()
    # slips of the keyboard ("the stvoe") read as the words they miss, as the rules planner reads them
    instruction = restructured(corrected(instruction, inventory))  # as the rules planner reads it
    for phrase in dict.fromkeys([*phrases_for(instruction), *extra]):
        try:
            keypoints[phrase] = resolver.resolve(phrase)
        except LabelNotFound:
            unresolved[phrase] = _why_unresolved(resolver, phrase)
    summary = summarise(keypoints) if keypoints else "perception found none of the objects mentioned"
    return SceneView(keypoints, summary, unresolved=unresolved, inventory=inventory)


def _why_unresolved(resolver: Resolver, phrase: str) -> str:
    """ "several match: N" when every prompt tried found several instances in some view, else "none found"."""
    records = getattr(resolver, "groundings", None) or [{}]
    record = records[-1]
    if record.get("label") != phrase:
        return "none found"
    if record.get("several"):  # one view kept a single detection, another saw several of it (resolver.py)
        return f"several match: {record['several']}"
    counts = [
        c["n_detections"] for cam in record.get("cameras", {}).values() for c in cam["candidates"] if c["n_detections"]
    ]
    return f"several match: {max(counts)}" if counts and min(counts) > 1 else "none found"


def arm_bases(world) -> dict[str, tuple[float, float]]:
    """Where each arm stands (base x, y in the world, m): what a planner needs to share work between arms."""
    return {
        a: (float(world.kinematics[a].T_world_base[0, 3]), float(world.kinematics[a].T_world_base[1, 3]))
        for a in world.arms
    }


def arm_tools(world) -> dict[str, str]:
    """Arms that carry a tool fixed in place of fingers, and the tool: such an arm wipes but cannot grasp."""
    tools = {a: world.kinematics[a].robot.gripper.mounted_tool for a in world.arms}
    return {a: t for a, t in tools.items() if t}


def annotated_view(view: SceneView, resolver: Resolver) -> SceneView:
    """Multimodal planners also get the first camera's image (agentview) with what perception kept drawn on it,
    as in the paper: each chosen detection's mask tinted and labelled, and the 3D keypoints (when the resolver
    looks through cameras at all)."""
    frames = getattr(resolver, "frames", None)
    if not frames:
        return view
    from ..perception.annotate import annotate

    camera, frame = next(iter(frames.items()))
    kept = getattr(resolver, "detections", {}).get(camera, {})
    detections = [d for label, d in kept.items() if label in view.keypoints]
    return SceneView(
        view.keypoints, view.summary, annotate(frame, detections, view.keypoints), view.unresolved, view.inventory
    )


def agentview_png(resolver: Resolver) -> bytes | None:
    """The first perception camera's current image (PNG), as the prompt-synthesis call receives it; None when
    the resolver looks through no cameras (privileged keypoints)."""
    cameras = getattr(resolver, "cameras", ())
    world = getattr(resolver, "world", None)
    if not cameras or world is None:
        return None
    from .llm import png_bytes

    w, h = getattr(resolver, "size", (640, 480))
    return png_bytes(world.render(cameras[0], w, h).rgb)


def perceive_for_llm(
    planner: Any, instruction: str, resolver: Resolver, *, adaptive: bool, k: int = 3, extra: Sequence[str] = ()
) -> tuple[SceneView, list[dict]]:
    """The paper's perception loop before an LLM's BT call, in its order: (a) the prompt-synthesis call on the
    task language and the agentview image gives the objects to detect and, when `adaptive`, `k` alternative
    prompts per object; (b, c) perception runs every prompt on every camera and keeps the single confident
    detection, for the instruction's own phrases, the LLM's objects and `extra` names; (d) the view carries the
    annotated image for the BT call. A failed synthesis call is recorded and perception keeps its synonym table.
    Returns the view and the synthesis call as the trace keeps it."""
    from .llm import PlannerUnavailable, TransientError

    objects: tuple[str, ...] = ()
    if hasattr(planner, "synthesise"):
        use_variants = getattr(resolver, "use_variants", None)
        try:
            synthesis = planner.synthesise(instruction, agentview_png(resolver), k if adaptive and use_variants else 0)
        except (TransientError, PlannerUnavailable) as e:
            planner.calls.append(
                {"kind": "prompt_synthesis", "error": f"{type(e).__name__}: {e}", "usage": {}, "cost_usd": 0.0}
            )
        else:
            objects = synthesis.objects
            if use_variants is not None and synthesis.variants:
                use_variants(synthesis.variants)
    view = annotated_view(observe(instruction, resolver, [*objects, *extra]), resolver)
    return view, list(getattr(planner, "calls", []))


def image_reference(view: SceneView, camera: str | None = None) -> dict | None:
    """What the call's trace record names of the image attached to the BT call: its camera, size and the SHA-256
    of the exact PNG sent (the PNG itself is the trial's `planner-input` artifact, see trace.artifacts)."""
    if view.image is None:
        return None
    import hashlib

    from .llm import png_bytes

    h, w = view.image.shape[:2]
    return {
        "camera": camera,
        "size_px": [w, h],
        "sha256": hashlib.sha256(png_bytes(view.image)).hexdigest(),
    }
