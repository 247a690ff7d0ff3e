"""Safe text -> data for plans: YAML or JSON, LLM wrappers removed, hostile input rejected fast.

Guards (each rejects with a PlanError naming what was wrong, never a crash or hang):
size cap, strict UTF-8, no YAML aliases (alias bombs), no tags that construct objects, bounded nesting.
"""

from __future__ import annotations

import json
import re
from typing import Any

import yaml

from .errors import PlanError, PlanIssue

MAX_PLAN_BYTES = 256 * 1024
MAX_NESTING = 64  # YAML/JSON container depth; real plans are < 10 deep
# Integer literals: no plan parameter needs more digits, and Python refuses to convert more than 4300 (ValueError)
MAX_INT_DIGITS = 100
_FENCE = re.compile(r"```[ \t]*([A-Za-z0-9_+-]*)[ \t]*\r?\n(.*?)```", re.DOTALL)
_STANDARD_TAGS = {"tag:yaml.org,2002:" + t for t in ("str", "int", "float", "bool", "null", "map", "seq")}


def _fail(path: str, message: str) -> PlanError:
    return PlanError([PlanIssue(path, message)])


class _TooLarge:
    """Stands in for an integer literal of more than MAX_INT_DIGITS digits until its path is known."""

    def __init__(self, digits: int):
        self.digits = digits


def _int_or_too_large(literal: str) -> int | _TooLarge:
    digits = sum(ch.isalnum() for ch in literal)
    return _TooLarge(digits) if digits > MAX_INT_DIGITS else int(literal)


def _refuse_too_large(data: Any, path: str = "") -> Any:
    """Raise a PlanError at the first oversized integer, named by its path (tree.params.lift_height)."""
    if isinstance(data, _TooLarge):
        raise _fail(path or "text", f"number too large ({data.digits} digits; at most {MAX_INT_DIGITS})")
    if isinstance(data, dict):
        for k, v in data.items():
            _refuse_too_large(v, f"{path}.{k}" if path else str(k))
    elif isinstance(data, list):
        for i, v in enumerate(data):
            _refuse_too_large(v, f"{path}[{i}]")
    return data


def _unique_keys(pairs: list[tuple[str, Any]]) -> dict[str, Any]:
    """json.loads keeps the last of repeated keys silently; a plan must not say two things at once."""
    out: dict[str, Any] = {}
    for key, value in pairs:
        if key in out:
            raise _fail("text", f"duplicate key {key!r}")
        out[key] = value
    return out


class _PlanLoader(yaml.SafeLoader):
    """SafeLoader that refuses aliases, non-standard tags and deep nesting at compose time."""

    def __init__(self, stream: str):
        super().__init__(stream)
        self._depth = 0

    def compose_node(self, parent, index):
        if self.check_event(yaml.AliasEvent):
            ev = self.peek_event()
            raise _fail("text", f"line {ev.start_mark.line + 1}: YAML aliases (*{ev.anchor}) are not allowed in plans")
        ev = self.peek_event()
        tag = getattr(ev, "tag", None)
        if tag not in (None, "!") and tag not in _STANDARD_TAGS:
            raise _fail("text", f"line {ev.start_mark.line + 1}: YAML tag {tag!r} is not allowed in plans")
        if getattr(ev, "anchor", None) is not None:
            raise _fail(
                "text",
                f"line {ev.start_mark.line + 1}: YAML anchors and aliases (&{ev.anchor}) are not allowed in plans",
            )
        nested = isinstance(ev, (yaml.MappingStartEvent, yaml.SequenceStartEvent))
        if nested:
            self._depth += 1
            if self._depth > MAX_NESTING:
                raise _fail("text", f"line {ev.start_mark.line + 1}: nesting deeper than {MAX_NESTING} levels")
        try:
            return super().compose_node(parent, index)
        finally:
            if nested:
                self._depth -= 1

    def construct_mapping(self, node, deep=False):
        seen: set = set()
        for key_node, _value in node.value:
            key = self.construct_object(key_node, deep=True)
            if isinstance(key, (str, int, float, bool)) or key is None:
                if key in seen:  # YAML keeps the last silently: a plan must not say two things at once
                    raise _fail("text", f"line {key_node.start_mark.line + 1}: duplicate key {key!r}")
                seen.add(key)
        return super().construct_mapping(node, deep=deep)

    def construct_yaml_int(self, node):
        digits = sum(ch.isalnum() for ch in str(node.value))  # hex and octal too
        if digits > MAX_INT_DIGITS:
            return _TooLarge(digits)
        return super().construct_yaml_int(node)


_PlanLoader.add_constructor("tag:yaml.org,2002:int", _PlanLoader.construct_yaml_int)


def _json_depth_ok(text: str) -> bool:
    """Bracket depth outside strings stays within MAX_NESTING (checked before json.loads recurses)."""
    depth = 0
    in_str = esc = False
    for ch in text:
        if in_str:
            if esc:
                esc = False
            elif ch == "\\":
                esc = True
            elif ch == '"':
                in_str = False
        elif ch == '"':
            in_str = True
        elif ch in "[{":
            depth += 1
            if depth > MAX_NESTING:
                return False
        elif ch in "]}":
            depth -= 1
    return True


def decode(text: str | bytes) -> str:
    """Bytes -> str with the size cap and strict UTF-8."""
    size = len(text) if isinstance(text, bytes) else len(text.encode("utf-8", "surrogatepass"))
    if size > MAX_PLAN_BYTES:
        raise _fail("text", f"plan is {size} bytes; the limit is {MAX_PLAN_BYTES} bytes")
    if isinstance(text, bytes):
        try:
            text = text.decode("utf-8")
        except UnicodeDecodeError as e:
            raise _fail("text", f"not valid UTF-8: byte 0x{text[e.start]:02x} at offset {e.start}") from None
    if "\x00" in text:
        raise _fail("text", f"NUL character at offset {text.index(chr(0))}")
    return text.lstrip("\ufeff")


def unfence(text: str) -> str:
    """The content of the first fenced code block, or the text unchanged when there is none."""
    m = _FENCE.search(text)
    return m.group(2) if m else text


def load_text(text: str) -> Any:
    """Parse YAML or JSON text into Python data, with every guard applied."""
    body = unfence(text).strip()
    if not body:
        raise _fail("text", "plan text is empty")
    if body[0] in "{[":
        if not _json_depth_ok(body):
            raise _fail("text", f"nesting deeper than {MAX_NESTING} levels")
        try:
            return _refuse_too_large(json.loads(body, parse_int=_int_or_too_large, object_pairs_hook=_unique_keys))
        except (json.JSONDecodeError, RecursionError):
            pass  # not strict JSON: YAML flow syntax may still read it
    try:
        return _refuse_too_large(yaml.load(body, Loader=_PlanLoader))
    except PlanError:
        raise
    except yaml.MarkedYAMLError as e:
        mark = e.problem_mark or e.context_mark
        where = f"line {mark.line + 1}, column {mark.column + 1}: " if mark else ""
        raise _fail("text", f"{where}invalid YAML/JSON: {e.problem or e.context}") from None
    except (yaml.YAMLError, RecursionError, ValueError) as e:  # ValueError: a literal Python cannot convert
        raise _fail("text", f"invalid YAML/JSON: {e}") from None


def unwrap(data: Any, _depth: int = 0) -> Any:
    """Remove the wrappers LLMs add: {"plan": {...}}, {"plan": "<yaml text>"}, a quoted YAML string.

    A wrapper is only taken off when what it holds is itself a plan (has a `tree`); otherwise the data is
    returned unchanged so the type-checker reports the real problem.
    """
    if _depth > 3:
        return data
    inner: Any = None
    if isinstance(data, str) and "tree" in data:
        try:
            inner = load_text(data)
        except PlanError:
            return data
    elif isinstance(data, dict) and "tree" not in data and len(data) == 1:
        (inner,) = data.values()
        if isinstance(inner, str) and "tree" in inner:
            try:
                inner = load_text(inner)
            except PlanError:
                return data
    if isinstance(inner, dict) and "tree" in inner:
        return unwrap(inner, _depth + 1)
    if isinstance(inner, dict) and len(inner) == 1:
        deeper = unwrap(inner, _depth + 1)
        return deeper if isinstance(deeper, dict) and "tree" in deeper else data
    return data
