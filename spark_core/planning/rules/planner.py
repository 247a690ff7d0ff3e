"""The `rules` planner: parse the instruction, ground each phrase in what perception saw, compose a tree."""

from __future__ import annotations

import re
import time
from collections.abc import Callable
from dataclasses import replace

import numpy as np

from ...grammar import PlanError, check_plan, to_yaml
from ...perception.qualifiers import split_relation
from ...perception.variants import CONSUMABLES, KIND_OF, PACKAGING
from ..protocol import PlanRequest, PlanResult
from .afford import Reading, unplaced_variety
from .afford import best as afforded
from .contradiction import contradicted
from .descriptions import descriptions
from .discourse import restructured
from .kinds import modifier_for_thing, other_contents, other_variety
from .lexicon import CLEANERS, CONTAINERS, CONTENTS, FIXED, REGIONS, SOLIDS, VERBS
from .mentions import clause_mentions, foreign_modifiers, read_past, stray_nouns
from .parse import Clause, ParseError, head_noun, is_pronoun, parse_instruction
from .phrases import singular
from .qualify import bare_rank
from .reader import describe, readings, unused_mentions
from .remarks import context_sentences, names_absent, only_what_is_there, remarks, trailing_remarks
from .spelling import corrected
from .stepwise import steps

POUR_ANGLE_RAD = 2.2
HANDLE_REACH_M = 0.25  # a handle further than this from the thing it opens belongs to something else
DIR_VECTORS = {"forward": (1.0, 0.0), "backward": (-1.0, 0.0), "left": (0.0, 1.0), "right": (0.0, -1.0)}


class CannotPlan(ValueError):
    pass


# Kinds of things that switch on and off (by a knob, dial or switch of their own), as the kinds table names them.
SWITCHED = frozenset(["stove", "oven", "microwave", "fridge", "toaster", "kettle", "blender", "lamp", "knob", "dial"])


class Impossible(CannotPlan):
    """What the sentence asks, read as said, cannot be done (a thing put inside one that is solid or too small, a
    solid thing turned on, the second of one thing): no other reading of it is tried in its place, so "put
    the basket inside the block" is never read as the block into the basket."""


def _prim(name: str, **params) -> dict:
    return {"primitive": name, "params": {k: v for k, v in params.items() if v is not None}}


class RulesPlanner:
    """Deterministic and offline. Says what it understood and what it did not when it cannot plan."""

    name = "rules"

    def __init__(self, fallback: bool = True):
        # the learned reader (planning/learned_reader) reads what every rule reading refuses, when it can
        self.fallback = fallback

    def prompt_variants(self, labels: list[str], k: int = 3) -> dict[str, list[str]]:
        """Deterministic variants from the label's words and a synonym table (no model call): the resolver's own,
        which never widen a label."""
        from ...perception.variants import prompt_variants

        return {label: prompt_variants(label, k) for label in labels}

    def plan(self, request: PlanRequest) -> PlanResult:
        t0 = time.perf_counter()
        task = request.instruction.strip()
        # slips of the keyboard read as the words they miss (rules/spelling.py), as observe looked for them
        request = replace(request, instruction=corrected(request.instruction, request.scene.inventory))
        # steps said out of order, context and contrast, headers, back-references: said plainly (rules/discourse.py)
        request = replace(request, instruction=restructured(request.instruction))
        if only_what_is_there(request.instruction):  # "there's a handle on the cabinet drawer.": nothing to do
            return self._refusal(CannotPlan(f"{task!r} only says what is there: say what to do with it"), [], t0)
        read = self._read(request, t0, stepwise=True)
        if isinstance(read, PlanResult):
            read = self._without_remarks(request, t0) or read
        if isinstance(read, PlanResult) and self.fallback:
            read = self._learned(read, request)
        if isinstance(read, PlanResult):
            return read
        children, understood = read
        # a thing said in another colour, material or size than the one planned, which perception did not find
        # (rules/afford.py): refused, whichever reading planned around it
        other = unplaced_variety(request.instruction, _labels(children), request.scene.unresolved)
        if other is not None:
            return self._refusal(
                CannotPlan(
                    f"could not find {other!r} in the scene: perception found nothing that matches it (found in "
                    f"the scene: {_seen(request)})"
                ),
                understood,
                t0,
            )
        # a state said of a planned thing that the plan undoes (rules/contradiction.py): nonsense, whoever read it
        against = contradicted(request.instruction, _leaves(children))
        if against is not None:
            return self._refusal(
                Impossible(
                    f"the instruction also asks for the opposite of what it asks: {against!r} cannot hold once the "
                    f"plan is done (understood: {'; '.join(understood)})"
                ),
                understood,
                t0,
            )
        data = {"task": task, "tree": {"type": "sequence", "children": children}}
        try:
            plan = check_plan(data)
        except PlanError as e:
            return self._untyped(e, t0)
        return PlanResult(
            self.name, to_yaml(plan), plan, latency_s=time.perf_counter() - t0, detail={"understood": understood}
        )

    def _without_remarks(self, request: PlanRequest, t0: float) -> tuple[list[dict], list[str]] | None:
        """The request read without the remark sentences after it, or else without the trailing clauses that only
        remark (rules/remarks.py), when every reading of the whole refused: None when there are none, one names a
        thing the scene lacks, or the rest does not plan."""
        kept, said = remarks(request.instruction)
        found = [*request.scene.keypoints, *request.scene.inventory]
        tries = [] if not said or any(names_absent(s, found) for s in said) else [(kept, said)]
        tries += [(k, [tail]) for k, tail in trailing_remarks(request.instruction, found)]
        from ..learned_reader.fallback import says_a_goal  # (the reader's test of a request, shared)

        kept, said = context_sentences(request.instruction, found, says_a_goal)
        tries += [(kept, said)] if said else []
        for kept, said in tries:
            read = self._read(replace(request, instruction=kept), t0, stepwise=True)
            if not isinstance(read, PlanResult):
                children, understood = read
                return children, [*understood, *(f"set aside as a remark: {s!r}" for s in said)]
        # the sentences that only describe set aside (rules/descriptions.py): the rest read as a whole request,
        # remarks and all (it has no description left, so this recursion ends)
        kept, said = descriptions(request.instruction, found)
        if said:
            rest = replace(request, instruction=restructured(kept))  # said alone, its own lead-in is plain
            read = self._read(rest, t0, stepwise=True)
            got = self._without_remarks(rest, t0) if isinstance(read, PlanResult) else read
            if got is not None:
                return got[0], [*got[1], *(f"set aside as a description: {s!r}" for s in said)]
        return None

    def _learned(self, refusal: PlanResult, request: PlanRequest) -> tuple[list[dict], list[str]] | PlanResult:
        """The learned reader's reading (planning/learned_reader) of what every rule reading refused; the refusal,
        with why the reader declined, when it does."""
        from ..learned_reader.fallback import may_read, read

        if not may_read(refusal.error, request):
            return refusal
        got = read(request, self)
        if got is None:
            return refusal
        if isinstance(got, str):
            return replace(refusal, error=f"{refusal.error} (the learned reader declined: {got})")
        return got

    def _untyped(self, e: PlanError, t0: float) -> PlanResult:
        """A composed plan the type checker rejects: a composition bug, reported rather than raised."""
        return PlanResult(
            self.name,
            "",
            None,
            issues=e.issues,
            error="the composed plan did not type-check",
            latency_s=time.perf_counter() - t0,
        )

    def _read(self, request: PlanRequest, t0: float, stepwise: bool) -> tuple[list[dict], list[str]] | PlanResult:
        """The steps and what was understood, by the first reading that grounds: the rule parse, the order-free
        reader, the scene-afforded reading, then (`stepwise`) each step of the instruction on its own; else the
        refusal."""
        understood: list[str] = []
        try:
            clauses = parse_instruction(request.instruction)
            understood = [_describe(c) for c in clauses]
            children = self._compose(clauses, request)
            children = _two_arm_branches(children, request) or children
            if unused_mentions(request.instruction, clauses):
                # a thing the sentence names that no step uses ("the bowl needs to be up on top of the cabinet"
                # read as a lift): the order-free reading, when exactly one grounds
                read = self._read_without_order(request)
                if read is not None:
                    children, understood = read
        except Impossible as e:
            return self._refusal(e, understood, t0)
        except (ParseError, CannotPlan) as e:
            read = self._read_without_order(request)
            if read is None:
                read, why = self._afforded(request)
                if read is None and stepwise:
                    read = self._by_steps(request, t0)
                if read is None and why.startswith("which ") and not str(e).startswith(("which ", "could not single")):
                    # several things fit a mention, and every other word said is placed: say so
                    return self._refusal(CannotPlan(f"{why} (found in the scene: {_seen(request)})"), understood, t0)
            if read is None:
                return self._refusal(e, understood, t0)
            children, understood = read
        except PlanError as e:  # a composition bug: report it rather than crash
            return self._untyped(e, t0)
        return children, understood

    def _by_steps(self, request: PlanRequest, t0: float) -> tuple[list[dict], list[str]] | None:
        """Each step of the instruction (rules/stepwise.py) read on its own by the whole pipeline, the steps joined;
        None when it has fewer than two steps or any step does not plan."""
        children: list[dict] = []
        understood: list[str] = []
        for text in steps(request.instruction):
            read = self._read(replace(request, instruction=text), t0, stepwise=False)
            if isinstance(read, PlanResult):
                return None
            step, said = read
            children += [c for c in step if c.get("primitive") != "go_home"]  # only the last step stands back
            understood += [f"step {text!r}: {s}" for s in said]
        if not children:
            return None
        if any(c.get("primitive") in FIXTURE_STEPS for c in children[-1:]):
            children.append(_prim("go_home"))
        joined = _free_hand(_carried_once(_one_grasp(children, request.scene.keypoints)))
        return (joined, understood) if _second_grasp(joined) is None else None

    def _refusal(self, e: Exception, understood: list[str], t0: float) -> PlanResult:
        if isinstance(e, ParseError):
            return PlanResult(
                self.name,
                "",
                None,
                error=f"did not understand the instruction: {e}",
                latency_s=time.perf_counter() - t0,
            )
        return PlanResult(
            self.name, "", None, error=str(e), latency_s=time.perf_counter() - t0, detail={"understood": understood}
        )

    def _read_without_order(self, request: PlanRequest) -> tuple[list[dict], list[str]] | None:
        """The order-free readings (reader.py) that ground: every phrase found, and the steps composed with the
        same checks as the rule parse's (every thing named in the scene, nothing put on itself). Accepted only
        when exactly one distinct plan comes of them; several that differ are an ambiguity, none a refusal."""
        scene = request.scene.keypoints
        plans: dict[tuple, tuple[list[dict], list[str]]] = {}
        for reading in readings(request.instruction):
            if not all(p in scene for c in reading for p in _grounded(c)):
                continue
            try:
                children = self._compose(reading, request)
            except CannotPlan:
                continue
            children = _two_arm_branches(children, request) or children
            plans.setdefault(_effect(children, scene), (children, [f"read without word order: {describe(reading)}"]))
        return next(iter(plans.values())) if len(plans) == 1 else None

    def _afforded(self, request: PlanRequest) -> tuple[tuple[list[dict], list[str]] | None, str]:
        """The reading the scene affords (rules/afford.py): the grounded mentions' best single-step goal, when it
        wins clearly and composes with the same checks as the rule parse's; else None and why not."""
        scene = request.scene.keypoints
        composed: dict[int, list[dict]] = {}

        def effect(reading: Reading) -> tuple | None:
            try:
                children = self._compose([reading.clause], request)
            except CannotPlan:
                return None
            children = _two_arm_branches(children, request) or children
            composed[id(reading)] = children
            return _effect(children, scene)

        chosen, why = afforded(request.instruction, scene, request.scene.unresolved, effect)
        if not chosen:
            return None, why
        return (composed[id(chosen[0])], [f"read from what the scene affords: {chosen[0].why}"]), ""

    # -- composition -------------------------------------------------------------------------------------------
    def _compose(self, clauses: list[Clause], request: PlanRequest) -> list[dict]:
        scene = request.scene.keypoints
        # what was found for the instruction's phrases, and what else the scene holds (when perception can list it)
        seen = (", ".join(scene) or "nothing") + (
            f"; the scene holds: {', '.join(request.scene.inventory)}" if request.scene.inventory else ""
        )
        understood = "; ".join(_describe(c) for c in clauses)

        def need(phrase: str | None, role: str, clause: Clause) -> str:
            if not phrase:
                raise CannotPlan(f"{clause.text!r}: which {role}? (understood: {_describe(clause)})")
            if phrase not in scene:
                why = request.scene.unresolved.get(phrase, "")
                if why.startswith("several match"):
                    n = why.rsplit(" ", 1)[-1]
                    head, relation, anchors = split_relation(phrase)
                    if relation:  # several of the kind, and where it is did not tell them apart
                        raise CannotPlan(
                            f"could not single out {phrase!r}: perception found {n} things that match {head!r} and "
                            f"could not tell which one is {relation} {' and '.join(anchors)!r} (is that there?) "
                            f"(understood: {understood}; found in the scene: {seen})"
                        )
                    raise CannotPlan(
                        f"which {phrase!r}? perception found {n} things that match it and nothing in the instruction "
                        f"says which one: name it by where it is or what it looks like (e.g. 'the left {phrase}', "
                        f"'the {phrase} next to ...') (understood: {understood}; found in the scene: {seen})"
                    )
                raise CannotPlan(
                    f"could not find {phrase!r} in the scene: perception found nothing that matches it "
                    f"(understood: {understood}; found in the scene: {seen})"
                )
            return phrase

        # safety: every thing the instruction names must be there, whatever its role: an object, a destination,
        # what another is located by, a noun the parser read past, or a noun no phrase holds (rules/mentions.py);
        # perception looked for each (observe) and found nothing
        said = [*clause_mentions(clauses), *read_past(request.instruction, clauses)]
        for phrase in [*said, *stray_nouns(request.instruction, clauses)]:
            if phrase not in scene and request.scene.unresolved.get(phrase, "").startswith("none"):
                raise CannotPlan(
                    f"could not find {phrase!r} in the scene: perception found nothing that matches it "
                    f"(understood: {understood}; found in the scene: {seen})"
                )
        # a thing named before a phrase's head noun ("the toaster plate", "the lego block") must be there too:
        # perception grounds the phrase by its head
        for word in foreign_modifiers([*said, *(c.obj for c in clauses if c.obj)], request.scene.inventory):
            raise CannotPlan(
                f"could not find {word!r} in the scene: nothing there is called that (understood: {understood}; "
                f"found in the scene: {seen})"
            )
        _check_kinds(said, clauses, request.scene.inventory, understood, seen)
        for phrase in {p for c in clauses for p in (c.obj, c.target, c.source, c.tool) if p}:
            kind = bare_rank(phrase)  # "the second plate" where perception singled out the one plate
            if kind and phrase in scene and kind in scene and _same_detection(scene[phrase], scene[kind]):
                raise Impossible(
                    f"could not find {phrase!r} in the scene: perception found one {kind!r} only "
                    f"(understood: {understood}; found in the scene: {seen})"
                )
        for c in clauses:  # "turn on the stove by pouring it into the bottle": a means no switch or drawer works by
            means = (
                re.search(r"\bby (\w+ing)\b", c.obj or "")
                if c.action in ("turn_on", "turn_off", "open", "close")
                else None
            )
            if means and _lemma(means.group(1)) in _MOVE_VERBS:
                raise Impossible(
                    f"{c.text!r}: {c.action.replace('_', ' ')} is not done by {means.group(1)} (understood: "
                    f"{understood}; found in the scene: {seen})"
                )
        for c in clauses:  # "put the stove on the plate": what is fixed in place is no thing to carry
            moved = c.obj if c.action in ("pick", "put", "stack", "push", "sort") else None
            if moved and not is_pronoun(moved) and _kind(moved) in FIXED and not c.together and not c.to_arm:
                # said right after a verb of carrying, it is what was asked: no other reading in its place
                stands = Impossible if _carried_as_said(_kind(moved), request.instruction) else CannotPlan
                raise stands(
                    f"{c.text!r}: {moved!r} is fixed in place (a {_kind(moved)} is not carried, pushed or lifted) "
                    f"(understood: {understood}; found in the scene: {seen})"
                )
        out: list[dict] = []
        last_object: str | None = None
        last_container: str | None = None
        held: str | None = None  # what the previous step left in the hand (a bare "pick X")
        put_last: str | None = None  # what the previous step set down somewhere
        opened: set[str] = set()  # drawers a step opened
        together: list[str] = []  # handles of a two-armed lift, gripped at once
        rests_on: dict[str, str] = {}  # what a step of this plan set down on or in what
        for _i, c in enumerate(clauses):
            obj = last_object if is_pronoun(c.obj) else c.obj
            target = (last_container or last_object) if is_pronoun(c.target) else c.target
            if target is None and c.relation == "in" and c.text.rstrip().endswith(("inside", "in", "into")):
                target = last_container  # "open the drawer and put the bowl inside"
            approach = c.action == "put" and _poured_next(obj, target, clauses[_i + 1 : _i + 2])
            if c.action == "mention":  # "there's a cup on the table; put it ...": only names the cup
                pass
            elif c.action == "put" and target is None and put_last == obj:
                pass  # "carry it to the basket and drop it in": the step before already put it there
            elif c.action == "put" and c.relation in ("in", "on") and _is_region(target):
                c = Clause("push", obj=obj, target=target, relation="in", text=c.text)  # into a flat area
                o = need(obj, "object", c)
                need(target, "region", c)
                direction, distance = self._push_geometry(c, o, target, scene)
                out.append(_prim("push_object", keypoint_label=o, direction=direction, distance=distance))
            elif c.action == "pick" and c.to_arm:
                out.append(_handoff(need(obj, "object", c), c.arm or "one", c.to_arm, request, scene))
            elif c.action == "pick" and c.together:
                together.append(need(obj, "handle", c))
                if len(together) == 2:
                    out += _lift_together(together, request)
                    together = []
            elif c.action == "pick" and held is not None and held == obj:
                pass  # "grab the cube and raise it": already in hand
            elif c.action == "pick":
                o = need(obj, "object", c)
                inside = re.search(r"\b(in|inside)\b", o) is not None  # out of a drawer or a box: clear its walls
                out.append(_prim("pick", keypoint_label=o, **({"lift_height": 0.2} if inside else {})))
            elif approach:
                pass  # "bring it over the bowl and tip it into the bowl": the carry is the pour's approach
            elif c.action == "put" and c.relation == "in" and _opened_later(target, clauses[_i + 1 :], last_object):
                pass  # "the cheese goes in the top drawer, so open it and put it inside": the goal, then its steps
            elif c.action == "put" and c.relation == "near" and "front of" in c.text:
                # "move the cheese to the front of the stove": a place on the table before a thing, reached by a push
                o = need(obj, "object", c)
                need(target, "destination", c)
                direction, distance = self._push_geometry(c, o, target, scene)
                out.append(_prim("push_object", keypoint_label=o, direction=direction, distance=distance))
            elif c.action in ("put", "sort", "stack"):
                o, t = need(obj, "object", c), need(target, "destination", c)
                if c.relation == "in" and "drawer" in t.split() and not _among(t, opened, scene):
                    # into a drawer that no step opened: drawers stand closed, so open it first
                    out.append(_drawer_step("open", t, scene, seen))
                    opened.add(t)
                if o == t or _same_detection(scene[o], scene[t]):
                    raise CannotPlan(
                        f"{c.text!r}: {o!r} and {t!r} are the same thing to perception: a thing cannot be put in or on "
                        f"itself (understood: {understood}; found in the scene: {seen})"
                    )
                if c.relation == "near":
                    raise CannotPlan(f"{c.text!r}: I can put things on or in something, not next to it")
                if _stands_on(t, o, rests_on, scene):  # "the blue block on the green one, the green on the blue"
                    raise Impossible(
                        f"{c.text!r}: after the steps before it, {t!r} rests on {o!r}, so {o!r} cannot go on {t!r} "
                        f"(understood: {understood}; found in the scene: {seen})"
                    )
                if c.relation == "in":
                    _check_fits(c.text, o, t, scene, f"(understood: {understood}; found in the scene: {seen})")
                pick = [] if held == o else [_prim("pick", keypoint_label=o)]  # "pick X and place it": X is in hand
                if c.action == "stack":
                    out += (
                        [_prim("place", target_label=t)]
                        if held == o
                        else [_prim("stack", keypoint_label=o, target_label=t)]
                    )
                elif c.relation == "in":
                    out += pick + [_prim("place_in", container_label=t)]
                else:
                    out += pick + [_prim("place", target_label=t)]
            elif c.action == "push":
                tail = f"(understood: {understood}; found in the scene: {seen})"
                if obj and _kind(obj) in REGIONS:  # "push the green area into the block": an area is no thing
                    raise Impossible(f"{c.text!r}: {obj!r} is a place on the table, not a thing to push {tail}")
                if target and c.relation == "in" and _kind(target) in SOLIDS:
                    raise Impossible(f"{c.text!r}: nothing goes into {target!r}: a {_kind(target)} is solid {tail}")
                o = need(obj, "object", c)
                if target:
                    need(target, "destination", c)
                direction, distance = self._push_geometry(c, o, target, scene)
                out.append(_prim("push_object", keypoint_label=o, direction=direction, distance=distance))
            elif c.action in ("open", "close"):
                o = need(obj, f"thing to {c.action}", c)  # the object itself must be seen, not only a handle-like part
                out.append(_drawer_step(c.action, o, scene, seen))
                if c.action == "open":
                    last_container = o
                    opened.add(o)
            elif c.action in ("turn_on", "turn_off"):
                obj = need(obj, "appliance", c)
                if _kind(obj) in SOLIDS:  # "turn on the red block": solid through, nothing on it turns
                    raise Impossible(
                        f"cannot turn {obj!r} {c.action[5:]}: a {_kind(obj)} has no knob or switch (understood: "
                        f"{understood}; found in the scene: {seen})"
                    )
                kind = _kind(obj)
                if kind in KIND_OF and not KIND_OF[kind] & SWITCHED:  # "turn on the wine rack": no appliance
                    raise Impossible(
                        f"cannot turn {obj!r} {c.action[5:]}: a {kind} is not something that switches on or off "
                        f"(understood: {understood}; found in the scene: {seen})"
                    )
                knob = obj if obj.split()[-1] in ("knob", "dial") else f"{obj} knob"  # "the stove's dial" is its knob
                plain = f"{obj.split()[-1]} knob"
                if (
                    knob in scene
                    and obj in scene
                    and plain in scene
                    and _same_detection(scene[knob], scene[obj])
                    and not _same_detection(scene[plain], scene[obj])
                ):
                    knob = plain  # "the grey stove": grey is the stove's colour, not its knob's (found as the stove)
                if knob not in scene:
                    raise CannotPlan(
                        f"cannot turn {obj!r} {c.action[5:]}: perception did not find it with a knob "
                        f"(looked for {obj!r} and {knob!r}; found: {seen})"
                    )
                out.append(_prim("turn_knob", keypoint_label=knob, angle=90.0 if c.action == "turn_on" else -90.0))
            elif c.action == "pour":
                dst = need(target, "container to pour into", c)
                product = _kind(dst) in CONSUMABLES or _kind(dst) in PACKAGING and set(dst.split()) & CONSUMABLES
                if product:  # "pour the basket into the milk carton": a product in its package, not a vessel
                    raise Impossible(
                        f"{c.text!r}: {dst!r} is a product in its package, not a container to pour into (understood: "
                        f"{understood}; found in the scene: {seen})"
                    )
                if _kind(dst) in SOLIDS:  # "pour the bowl into the red block": nothing goes into a solid thing
                    raise Impossible(
                        f"{c.text!r}: nothing can be poured into {dst!r}: a {_kind(dst)} is solid, it holds nothing "
                        f"(understood: {understood}; found in the scene: {seen})"
                    )
                src = need(_holder_of(c.source or obj, dst, scene), "container to pour from", c)
                if _kind(src) in _FLAT | _FRAMES | set(SOLIDS):  # "pour the plate into the ramekin": nothing to pour
                    raise Impossible(
                        f"{c.text!r}: {src!r} {'is flat and ' if _kind(src) in _FLAT else ''}holds nothing to pour "
                        f"(a {_kind(src)}; understood: {understood}; found in the scene: {seen})"
                    )
                if src == dst or _same_detection(scene[src], scene[dst]):  # "pour the mug into the mug"
                    raise Impossible(
                        f"{c.text!r}: {src!r} and {dst!r} are the same thing to perception: nothing pours into itself "
                        f"(understood: {understood}; found in the scene: {seen})"
                    )
                if held == src and out and out[-1]["primitive"] == "pick":
                    out.pop()  # "pick up the mug and pour it": pouring grasps it from the side itself
                out += [
                    _prim("grasp_se3", keypoint_label=src, strategy="side", force=40.0),
                    _prim("lift", height=0.12),
                    _prim("pour", target_label=dst, pour_angle=POUR_ANGLE_RAD),
                ]
            elif c.action == "scrub":
                t = need(target or obj, "surface to scrub", c)
                # said without a tool: the one cleaning tool perception found, if it found exactly one
                cleaner = None if c.tool or request.tools else _the_one(CLEANERS, t, scene)
                if not c.tool and request.tools:  # an arm carries a wiping pad: wipe the region clean with it
                    out.append(_prim("wipe_area", keypoint_label=t))
                elif not c.tool and not cleaner:
                    raise CannotPlan(f"{c.text!r}: scrub with what? say e.g. 'with the sponge'")
                else:
                    tool = need(c.tool, "tool", c) if c.tool else str(cleaner)
                    if tool == t or _same_detection(scene[tool], scene[t]):
                        # one thing found for both: the tool named is not there (a "dish towel" found as the plate)
                        raise CannotPlan(
                            f"{c.text!r}: {tool!r} and {t!r} are the same thing to perception: nothing scrubs itself "
                            f"(understood: {understood}; found in the scene: {seen})"
                        )
                    out += [] if held == tool else [_prim("pick", keypoint_label=tool)]  # already in hand
                    out += [
                        _prim("constrained_scrub", target_label=t),
                        _prim("move_relative", dz=0.10),
                        _prim("release"),
                    ]
            put_last = obj if c.action in ("put", "stack") and target else None
            if obj and c.action in ("put", "stack", "sort", "pick", "push"):
                # moved again: no longer where an earlier step set it
                rests_on = {k: v for k, v in rests_on.items() if not (k == obj or _same_label(k, obj, scene))}
                if put_last and target:
                    rests_on[obj] = target
            held = obj if c.action == "pick" else held if c.action == "mention" or approach else None
            last_object = obj or last_object
        if together:
            raise CannotPlan(f"lifting {together[0]!r} with both arms needs a second handle for the other arm")
        for c in clauses:
            if c.unread:  # a part no step uses, e.g. a step said in a way not read: refused, never dropped (issue 18)
                raise CannotPlan(
                    f"could not read {c.text!r}: it names {c.obj!r} but says nothing I can do with it, and no step "
                    f"after it uses it (understood: {understood}; found in the scene: {seen})"
                )
        if clauses and clauses[-1].action in ("open", "close", "turn_on", "turn_off"):
            out.append(_prim("go_home"))  # leave the fixture's neighbourhood
        out = _free_hand(_carried_once(_one_grasp(out, scene)))
        wrong = _second_grasp(out)
        if wrong is not None:
            raise CannotPlan(f"{wrong} (understood: {understood}; found in the scene: {seen})")
        return out

    @staticmethod
    def _push_geometry(c: Clause, obj: str, target: str | None, scene) -> tuple[str, float]:
        """Direction and distance: as said, or from where the target region is relative to the object."""
        if target and target in scene:
            delta = scene[target].position_m[:2] - scene[obj].position_m[:2]
            direction = c.direction or max(DIR_VECTORS, key=lambda d: float(np.dot(delta, DIR_VECTORS[d])))
            distance = float(np.dot(delta, DIR_VECTORS[direction]))
            if distance <= 0.01:
                raise CannotPlan(f"{target!r} is not {direction} of {obj!r}")
            return direction, round(min(distance, 0.5), 3)
        if target:
            raise CannotPlan(f"could not find {target!r} in the scene")
        if not c.direction:
            raise CannotPlan(f"{c.text!r}: push which way? (forward, backward, left, right, or into something)")
        return c.direction, round(min(c.distance_m or 0.10, 0.5), 3)


def composer(
    planner: RulesPlanner, request: PlanRequest
) -> tuple[Callable[[list[Clause]], list[dict]], Callable[[list[dict]], tuple]]:
    """The planner's composition of clauses into checked steps (ValueError when its checks refuse), and the effect
    of steps in the request's scene: for readers outside this module (planning/learned_reader)."""

    scene = request.scene.keypoints

    def compose(clauses: list[Clause]) -> list[dict]:
        for c in clauses:  # two roles of one step said with two phrases perception found as one thing
            said = [p for p in (c.obj, c.target, c.source, c.tool) if p in scene]
            if any(_same_detection(scene[a], scene[b]) for i, a in enumerate(said) for b in said[i + 1 :] if a != b):
                raise CannotPlan(f"{_describe(c)}: two of its things are one thing to perception")
        children = planner._compose(clauses, request)
        children = _two_arm_branches(children, request) or children
        check_plan({"task": "t", "tree": {"type": "sequence", "children": children}})
        return children

    return compose, lambda children: _effect(children, request.scene.keypoints)


def _stands_on(top: str, base: str, rests_on: dict[str, str], scene) -> bool:
    """`top` rests on `base`, directly or through the things between, as the plan's steps so far set them down (a
    thing said two ways, "the green" and "the green block", is one thing when perception found them as one)."""

    def same(a: str, b: str) -> bool:
        return a == b or _same_label(a, b, scene)

    for _ in range(len(rests_on)):
        below = next((t for k, t in rests_on.items() if same(k, top)), None)
        if below is None:
            return False
        if same(below, base):
            return True
        top = below
    return False


def _same_label(a: str, b: str, scene) -> bool:
    """Two labels perception found as one thing."""
    return a in scene and b in scene and _same_detection(scene[a], scene[b])


def _leaves(steps: list[dict]) -> list[dict]:
    """The steps' primitives in order, nested branches too."""
    return [leaf for step in steps for leaf in (_leaves(step["children"]) if "children" in step else [step])]


def _labels(steps: list[dict]) -> list[str]:
    """Every object label of the steps, nested branches too."""
    out: list[str] = []
    for step in steps:
        out += _labels(step.get("children", []))
        out += [v for k, v in step.get("params", {}).items() if k.endswith("_label") and isinstance(v, str)]
    return out


def _seen(request: PlanRequest) -> str:
    """What perception found for the instruction's phrases, and what else the scene holds when it can list it."""
    scene = request.scene
    return (", ".join(scene.keypoints) or "nothing") + (
        f"; the scene holds: {', '.join(scene.inventory)}" if scene.inventory else ""
    )


def _check_kinds(
    said: list[str], clauses: list[Clause], inventory: tuple[str, ...], understood: str, seen: str
) -> None:
    """Every noun names a thing the scene holds, not a neighbour of it (rules/kinds.py): refused otherwise."""
    tail = f"(understood: {understood}; found in the scene: {seen})"
    for phrase in said:
        if is_pronoun(phrase):
            continue
        word = other_variety(phrase, inventory) or modifier_for_thing(phrase, inventory)
        if word:
            raise CannotPlan(f"could not find {phrase!r} in the scene: nothing there is a {word!r} {tail}")
    for c in clauses:
        if c.action == "pour" and c.obj and not is_pronoun(c.obj) and (c.source or c.obj.split()[-1] in CONTENTS):
            word = other_contents(c.obj, inventory)
            if word:
                raise CannotPlan(
                    f"could not find {c.obj!r} in the scene: what is there to pour is not {word!r} (the scene shows "
                    f"no {word!r}, and no {word!r} is taken on the sentence's word alone; 'the contents' pours "
                    f"whatever it holds) {tail}"
                )


FIXTURE_STEPS = ("open_drawer", "close_drawer", "turn_knob")


# Steps after which the hand is empty again.
_LETS_GO = frozenset(["place", "place_in", "stack", "place_over", "insert", "release", "drag"])


def _second_grasp(steps: list[dict]) -> str | None:
    """One hand holds one thing: a pick while the thing picked before is still held ("pick up the red block, put it
    on the table, then pick up the blue one", where nothing was read as setting it down) would drop or crush it.
    What is wrong, naming both; None when no step does so. Plans for more than one arm are not checked here."""
    if any("primitive" not in s or "arm" in s.get("params", {}) for s in steps):
        return None
    held: str | None = None
    for step in steps:
        kind, label = step["primitive"], step.get("params", {}).get("keypoint_label")
        if kind == "pick":
            if held is not None and label != held:
                return f"the plan would pick up {label!r} while still holding {held!r}: say where {held!r} goes first"
            held = label
        elif kind in _LETS_GO:
            held = None
    return None


def _free_hand(steps: list[dict]) -> list[dict]:
    """A fixture is worked with the hand free: a thing picked up just before a drawer is opened or a knob turned,
    and picked up again after it ("grab the block, open the drawer and put it inside"), is picked up after it only."""
    out = []
    for i, step in enumerate(steps):
        label = step.get("params", {}).get("keypoint_label")
        if (
            step.get("primitive") == "pick"
            and i + 1 < len(steps)
            and steps[i + 1].get("primitive") in FIXTURE_STEPS
            and any(s.get("primitive") == "pick" and s["params"].get("keypoint_label") == label for s in steps[i + 2 :])
        ):
            continue
        out.append(step)
    return out


def _one_grasp(steps: list[dict], scene) -> list[dict]:
    """Steps planned one by one: a pick of what the step before already picked up ("grab X." then "put X in Y")
    is the same grasp; a drawer opened (or shut) right after the same opening is the request said again ("open
    the drawer. open the cabinet drawer.")."""
    out: list[dict] = []
    for step in steps:
        if (
            step.get("primitive") in ("pick", "open_drawer", "close_drawer")
            and out
            and _same_step(out[-1], step, scene)
        ):
            continue
        out.append(step)
    return out


def _same_step(a: dict, b: dict, scene) -> bool:
    """One step, or two whose only difference is a label perception resolved to the same thing ("drawer handle",
    "cabinet drawer handle")."""
    if a == b:
        return True
    pa, pb = dict(a.get("params", {})), dict(b.get("params", {}))
    la, lb = pa.pop("keypoint_label", None), pb.pop("keypoint_label", None)
    return (
        a.get("primitive") == b.get("primitive")
        and pa == pb
        and la in scene
        and lb in scene
        and _same_detection(scene[la], scene[lb])
    )


def _carried_once(steps: list[dict]) -> list[dict]:
    """A carry said again right after it is done ("place it in the basket; target pose is inside the basket"): the
    same pick and place twice in a row is one carry; the thing is already there."""
    out: list[dict] = []
    for step in steps:
        if (
            step.get("primitive") in ("place", "place_in")
            and len(out) >= 3
            and out[-1].get("primitive") == "pick"
            and [out[-3], out[-2]] == [out[-1], step]
        ):
            out.pop()
            continue
        out.append(step)
    return out


def _holder_of(source: str | None, dst: str, scene) -> str | None:
    """What contents named without their container ("the beads should end up in the bowl") are poured from: the
    one container perception found besides the destination; the phrase itself when it names no contents, or when
    perception found no such container or several."""
    if not source or source in scene or source.split()[-1] not in CONTENTS:
        return source
    return _the_one(CONTAINERS, dst, scene) or source


def _the_one(words: tuple[str, ...], besides: str, scene) -> str | None:
    """The one thing perception found under any of `words` apart from `besides` (several words may find the same
    detection: "sponge", "scrubber"); None when it found none or several."""
    found = [w for w in words if w in scene and not _same_detection(scene[w], scene[besides])]
    distinct = [w for i, w in enumerate(found) if not any(_same_detection(scene[w], scene[g]) for g in found[:i])]
    return distinct[0] if len(distinct) == 1 else None


def _drawer_step(action: str, o: str, scene, seen: str) -> dict:
    """open_drawer / close_drawer by the handle perception found on `o` (refused when there is none on it), or by
    `o` itself when it is a drawer's handle ("take hold of the drawer handle and push it shut")."""
    handle = o if o.split()[-1] == "handle" and "drawer" in o.split() else _handle_on(action, o, scene, seen)
    if action == "open":
        # fully: into the end stop if it comes first (LIBERO's drawers count as open past 14 of 16 cm)
        return _prim("open_drawer", keypoint_label=handle, distance=0.18)
    return _prim("close_drawer", keypoint_label=handle)


def _handle_on(action: str, o: str, scene, seen: str) -> str:
    """The handle perception found on `o`; refused when it found none, or only `o` itself, or one too far away."""
    said = [h for h in (f"{o} handle", "drawer handle" if "drawer" in o.split() else "") if h in scene]
    # a handle phrase perception took for the drawer itself is passed over for one it found apart from it
    handle = next((h for h in said if not _same_detection(scene[h], scene[o])), said[0] if said else None)
    if handle is None:
        raise CannotPlan(
            f"cannot {action} {o!r}: perception found no handle on it (looked for {o + ' handle'!r}; found: {seen})"
        )
    if _same_detection(scene[handle], scene[o]):
        raise CannotPlan(
            f"cannot {action} {o!r}: perception found no handle on it, only {o!r} itself "
            f"(looked for {handle!r}; found: {seen})"
        )
    gap_m = np.linalg.norm(scene[handle].position_m - scene[o].position_m)
    if gap_m > HANDLE_REACH_M:
        raise CannotPlan(
            f"cannot {action} {o!r}: the handle perception found ({handle!r}) is not on it ({gap_m:.2f} m away)"
        )
    return handle


def _among(label: str, labels: set[str], scene) -> bool:
    """`label` is one of `labels`, by name or as the same detection ("cabinet drawer" opened, "the drawer" filled)."""
    return label in labels or any(x in scene and _same_detection(scene[x], scene[label]) for x in labels)


# Flat things: nothing to pour stays on them.
_FLAT = frozenset(["plate", "saucer", "platter", "board", "mat", "lid", "coaster"])
# Frames and furniture that hold things standing in or on them, nothing poured out of them ("pour the wine rack").
_FRAMES = frozenset(["rack", "stand", "shelf", "cabinet", "stove", "table"])


def _poured_next(obj: str | None, target: str | None, after: list[Clause]) -> bool:
    """The next clause pours the thing just carried (by name or as "it") into where it was carried."""
    return bool(obj and target) and any(
        c.action == "pour" and c.target == target and (c.obj == obj or c.source == obj or is_pronoun(c.obj))
        for c in after
    )


def _opened_later(target: str | None, later: list[Clause], last_object: str | None) -> bool:
    """A drawer that a later clause of the instruction opens (by name or as "it")."""
    if not target or "drawer" not in target.split():
        return False
    return any(c.action == "open" and (c.obj == target or is_pronoun(c.obj)) for c in later)


TWO_ARM_LIFT_M = 0.15


def _handoff(label: str, giver: str, receiver: str, request: PlanRequest, scene) -> dict:
    """One arm picks `label` (by its handle when perception found one) and hands it to the other: "one" is the
    arm whose base is nearer the object (or the arm not named as the receiver), "other" the arm not giving."""
    arms = sorted(request.arms)
    if len(arms) != 2:
        raise CannotPlan(f"handing {label!r} from one arm to another needs two arms; this robot has {len(arms)}")
    grip = f"{label} handle" if f"{label} handle" in scene else label
    if giver == "one":
        xy = scene[grip].position_m[:2]
        nearer = min(arms, key=lambda a: float(np.linalg.norm(xy - np.asarray(request.arms[a]))))
        giver = next(a for a in arms if a != receiver) if receiver in arms else nearer
    if receiver == "other":
        receiver = next(a for a in arms if a != giver)
    for arm in (giver, receiver):
        if arm not in arms:
            raise CannotPlan(f"this robot's arms are {' and '.join(arms)}: it has no {arm} arm")
    if giver == receiver:
        raise CannotPlan(f"hand {label!r} from the {giver} arm to itself? name two different arms")
    return _prim("handoff", keypoint_label=grip, from_arm=giver, to_arm=receiver)


def _lift_together(handles: list[str], request: PlanRequest) -> list[dict]:
    """Each handle to the arm whose base is nearer (the pairing with the shorter total reach), both gripped at
    once, then both arms lift together."""
    if len(request.arms) != 2:
        raise CannotPlan(
            f"lifting by {handles[0]!r} and {handles[1]!r} at once needs two arms; this robot has {len(request.arms)}"
        )
    scene = request.scene.keypoints
    a, b = sorted(request.arms)

    def reach(arm: str, label: str) -> float:
        return float(np.linalg.norm(scene[label].position_m[:2] - np.asarray(request.arms[arm])))

    first, second = handles
    if reach(a, first) + reach(b, second) > reach(a, second) + reach(b, first):
        first, second = second, first
    grips = [(a, first), (b, second)]
    return [
        {
            "type": "parallel",
            "children": [_prim("pick_with_arm", arm=arm, keypoint_label=h, lift_height=0.0) for arm, h in grips],
        },
        {"type": "parallel", "children": [_prim("lift", arm=arm, height=TWO_ARM_LIFT_M) for arm, _ in grips]},
    ]


CARRY_ENDS = ("place", "place_in")


def _two_arm_branches(steps: list[dict], request: PlanRequest) -> list[dict] | None:
    """On a two-arm robot, independent carries (pick X, then place / place_in Y) are shared out: each to the
    arm whose base is closer to its object and its destination together (sum of the two reaches), the two arms'
    carries in parallel (the paper's bimanual silverware sort); two carries to one destination grasp in parallel
    and set down in turn. None when the plan is not made of such carries, or one arm would get them all."""
    if len(request.arms) != 2 or len(steps) < 4 or len(steps) % 2:
        return None
    pairs = [steps[i : i + 2] for i in range(0, len(steps), 2)]
    if not all(p[0]["primitive"] == "pick" and p[1]["primitive"] in CARRY_ENDS for p in pairs):
        return None
    scene = request.scene.keypoints
    arms = sorted(request.arms)
    branches: dict[str, list[dict]] = {a: [] for a in arms}
    for pick, put in pairs:
        labels = [pick["params"]["keypoint_label"], next(iter(put["params"].values()))]
        if not all(lb in scene for lb in labels):
            return None
        # the whole way: a shared destination (one tray between the arms) is as far from both, and the object decides
        reach = {
            a: sum(float(np.linalg.norm(scene[lb].position_m[:2] - np.asarray(request.arms[a]))) for lb in labels)
            for a in arms
        }
        arm = min(arms, key=reach.__getitem__)
        branches[arm] += [{"primitive": "pick_with_arm", "params": dict(pick["params"])}, put]
    if not all(branches.values()):
        return None
    ends = [next(iter(put["params"].values())) for _, put in pairs]
    if len(pairs) == 2 and ends[0] == ends[1]:
        # one destination for both: grasp at once, then set down one arm after the other (each then stands
        # back), as two hands at the same spot would meet
        return [
            {
                "type": "parallel",
                "children": [{"type": "sequence", "arm": a, "children": branches[a][:1]} for a in arms],
            },
            *({"type": "sequence", "arm": a, "children": [branches[a][1], _prim("go_home")]} for a in arms),
        ]
    return [{"type": "parallel", "children": [{"type": "sequence", "arm": a, "children": branches[a]} for a in arms]}]


def _grounded(c: Clause) -> list[str]:
    """The phrases of a clause perception must have found: all of them, but for contents poured out of a
    container named with them ("the beads out of the mug": out of sight inside it)."""
    poured = c.action == "pour" and c.obj and c.source and c.obj.split()[-1] in CONTENTS
    return [p for p in (c.obj, c.target, c.source) if p and not is_pronoun(p) and not (poured and p == c.obj)]


def _effect(steps: list[dict], scene) -> tuple:
    """What steps do, by where their labels are (cm): two readings that name one thing two ways are one plan."""
    out = []
    for step in steps:
        params = step.get("params", {})
        out.append(
            (
                step.get("primitive"),
                tuple(
                    (k, tuple(np.round(scene[v].position_m * 100).astype(int)) if v in scene else v)
                    for k, v in sorted(params.items())
                ),
            )
        )
    return tuple(out)


# How much wider than a container, across its narrowest side, a thing may look and still go inside it: perception's
# extents are loose (a mask's spill, a bowl seen at a slant), so only a thing clearly too big is refused.
FITS_MARGIN = 1.2


# The first words of the lexicon's verbs of carrying, pushing and stacking ("pick" of "pick up", "shove", "place").
_CARRY_VERBS = frozenset(f.split()[0] for a in ("pick", "put", "stack", "push", "sort") for f in VERBS[a])
# Verbs that move or pour a thing or scrub with it: no means of switching or opening ("by pouring it into ...").
_MOVE_VERBS = frozenset(f.split()[0] for a in ("put", "stack", "sort", "pour", "scrub") for f in VERBS[a]) - {"turn"}


def _lemma(gerund: str) -> str:
    """ "pouring" -> "pour" (the lexicon's verb lemma)."""
    from lemminflect import getLemma

    lemmas = getLemma(gerund, upos="VERB")
    return lemmas[0] if lemmas else gerund


def _carried_as_said(kind: str, instruction: str) -> bool:
    """`kind` is said within four words after a verb of carrying ("pick up the stove", "put the flat stove in"),
    not only read into a clause by the parser ("the middle one of the cabinet's drawers, pull it open")."""
    words = re.findall(r"[a-z]+", instruction.lower())
    return any(
        singular(w) == kind and any(v in _CARRY_VERBS for v in words[max(0, i - 4) : i]) for i, w in enumerate(words)
    )


def _kind(phrase: str) -> str:
    """The head noun, singular ("green blocks next to bowl" -> "block"): what kind of thing a phrase names."""
    return singular(head_noun(phrase))


def _check_fits(text: str, o: str, t: str, scene, tail: str) -> None:
    """Refused: putting a thing inside one that is solid through ("inside the green block"), or inside one
    perception sees as clearly narrower than it ("the basket into the butter")."""
    kind = _kind(t)
    if kind in SOLIDS:
        raise Impossible(f"{text!r}: nothing goes inside {t!r}: a {kind} is solid, it holds nothing {tail}")
    thing_m = float(np.min(scene[o].extent_m[:2]))
    room_m = float(np.max(scene[t].extent_m[:2]))
    if room_m > 0 and thing_m > FITS_MARGIN * room_m:
        raise Impossible(
            f"{text!r}: {o!r} ({thing_m:.2f} m across) does not fit inside {t!r} ({room_m:.2f} m across) {tail}"
        )


def _same_detection(a, b) -> bool:
    """Two labels perception resolved to one and the same thing (same centre and extent)."""
    return bool(np.allclose(a.position_m, b.position_m, atol=1e-3) and np.allclose(a.extent_m, b.extent_m, atol=1e-3))


def _is_region(phrase: str | None) -> bool:
    return phrase is not None and phrase.split()[-1] in REGIONS


def _describe(c: Clause) -> str:
    parts = [c.action.replace("_", " ")]
    for name in ("obj", "relation", "target", "source", "tool", "direction"):
        v = getattr(c, name)
        if v:
            parts.append(f"{name}={v}")
    if c.distance_m:
        parts.append(f"distance={c.distance_m:.2f} m")
    return " ".join(parts)
