"""A request written as a spec of keyed fields, as a test log or a batch script says it: "obj: red block; dst: white
bowl", "action: push; obj: red block; dst: green target area", "src: cream cheese (near left corner); dst: bowl".

The fields are said as the sentence they stand for ("put the red block to the white bowl"), so the rest of the
rules read it as any request: each value is still a phrase perception must find, and a spec naming a thing the
scene lacks is refused as any sentence is. A text that is not every part a known key and its value is left alone.
"""

from __future__ import annotations

import re

# The keys of a spec's fields, by what they say: the thing moved, where it goes, where it comes from, the action.
KEYS: dict[str, str] = {
    **dict.fromkeys(["obj", "object", "item", "thing", "target object", "what", "pick"], "thing"),
    **dict.fromkeys(["object to move", "item to move", "moved object", "surface", "subject"], "thing"),
    **dict.fromkeys(
        ["dst", "dest", "destination", "to", "goal", "place", "where", "target", "tgt", "loc", "into"], "to"
    ),
    **dict.fromkeys(["target location", "location", "target place", "destination location", "goes to"], "to"),
    **dict.fromkeys(["src", "source", "from"], "from"),
    **dict.fromkeys(["tool", "using", "with", "implement"], "with"),
    **dict.fromkeys(["action", "act", "verb", "op", "do", "task", "skill"], "action"),
    **dict.fromkeys(["outcome", "result", "state", "end state", "desired state", "final state"], "outcome"),
}
# An outcome said as the state a thing ends in ("outcome: scrubbed"): the action that leaves it so.
_OUTCOMES = {
    **dict.fromkeys(["scrubbed", "clean", "cleaned", "wiped", "scoured"], "scrub"),
    **dict.fromkeys(["open", "opened"], "open"),
    **dict.fromkeys(["closed", "shut"], "close"),
    "on": "turn on",
    "off": "turn off",
    **dict.fromkeys(["lifted", "raised", "picked up", "up", "held"], "pick up"),
}
# Where a destination's value already says how the thing goes there ("inside akita black bowl").
_PREP = r"(?:in|into|inside|on|onto|on top of|next to|in front of|to|under|beside|behind)"


def spelled_out(text: str) -> str:
    """The spec in `text` said as a sentence; `text` itself when it is no spec. A lone goal after "tgt:" is said
    after "target:" ("tgt: bbq sauce in basket")."""
    text = re.sub(r"^tgt\s*:", "target:", text)
    # a header before the fields ("task card -- surface: plate; ..."): what the line is, no field of it
    text = re.sub(r"^(?:task card|card|spec|note|todo|eval|task)\s*(?:-+|:)\s*(?=[a-z ]+\s*[:=])", "", text)
    # "desired state of the flat stove: on": the state a thing ends in, said as its action
    m = re.fullmatch(
        r"(?:the )?(?:desired|target|final|end|goal|wanted) state of ((?:the )?[a-z ]+?)\s*[:=]\s*(\w+)\.?", text
    )
    if m and m.group(2) in _OUTCOMES:
        return f"{_OUTCOMES[m.group(2)]} the {_bare(m.group(1))}"
    # "basket contents: alphabet soup": what ends up in the container
    m = re.fullmatch(r"(?:the )?([a-z]+(?: [a-z]+)?) contents?\s*[:=]\s*([a-z ]+?)\.?", text)
    if m and not re.search(r"\b(?:and|or|nothing|empty)\b", m.group(2)):
        return f"put the {_bare(m.group(2))} in the {m.group(1)}"
    # fields one to a sentence ("object: cube. place: on top of the other cube.")
    parts = [
        p.strip() for p in re.split(r"\s*[;|\n]\s*|\.\s+(?=[a-z ]+\s*[:=])", text.strip().rstrip(".")) if p.strip()
    ]
    if len(parts) == 1 and text.count(":") + text.count("=") > 1:  # "obj: milk, dest: basket": fields between commas
        parts = [p.strip() for p in re.split(r"\s*,\s*", text.strip().rstrip(".")) if p.strip()]
    fields: dict[str, str] = {}
    for part in parts:
        m = re.fullmatch(r"([a-z ]+?)\s*[:=]\s*(.+)", part.lower())
        if not m or m.group(1) not in KEYS or KEYS[m.group(1)] in fields:
            return text
        fields[KEYS[m.group(1)]] = m.group(2).strip()
    if len(fields) < 2:
        return text
    thing, to, source = fields.get("thing"), fields.get("to"), fields.get("from")
    if thing is None and source is not None:
        thing, source = source, None  # "src: cream cheese; dst: bowl": the thing taken from where it is
    outcome = _OUTCOMES.get(fields.pop("outcome", "").rstrip("."))
    if outcome is not None and "action" not in fields:
        fields["action"] = outcome  # "surface: plate; tool: sponge; outcome: scrubbed"
    if thing is None or (to is None and "action" not in fields):
        return text
    # where a thing is, said in parentheses, says which one: "cream cheese (near left corner)"
    thing = re.sub(r"\s*\(\s*([^()]+?)\s*\)", r" \1", thing)
    said = f"{fields.get('action', 'put')} the {_bare(thing)}"
    if source is not None:
        said += f" from the {_bare(source)}"
    if to is not None:
        prep = re.match(rf"{_PREP}\b", to)
        said += f" {to}" if prep else f" to the {_bare(to)}"
    if "with" in fields:
        said += f" with the {_bare(fields['with'])}"
    return said


def _bare(phrase: str) -> str:
    """The phrase without its own article ("the bowl" -> "bowl")."""
    return re.sub(r"^(?:the|a|an)\s+", "", phrase)
