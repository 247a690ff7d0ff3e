"""Model names a caller gives an LLM planner, checked against the characters that vendor's names use.

Gemini puts the model name into the request's URL path (`.../v1beta/models/{model}:generateContent`): a `/`, `:`,
`#`, `%` or space there changes which URL is called (another resource, another method, a fragment), and the
google-genai client refuses only `..`, `?` and `&`. An OpenAI-compatible server gets the name in the JSON body,
where such characters are harmless but still never part of a model's name. So a name is letters, digits, `.`,
`-` and `_`, plus, where the vendor uses them: Gemini's `models/` or `tunedModels/` prefix; for OpenAI-compatible
servers `/` between parts (`Qwen/Qwen2.5-VL-7B-Instruct`, `hf.co/org/repo`) and `:` for a tag (`qwen3:8b`).
"""

from __future__ import annotations

import re
import unicodedata

_WORD = "letters, digits, '.', '-' and '_'"
_PART = re.compile(r"[A-Za-z0-9][A-Za-z0-9._-]*")  # starts with a letter or digit: no '.', '..' or '-x' parts

# planner -> (extra characters its names may hold, how its names are written)
_RULES: dict[str, tuple[str, str]] = {
    "gemini": ("/", f"a Gemini model name is {_WORD}, after an optional 'models/' or 'tunedModels/' prefix"),
    "openai": (
        "/:",
        f"an OpenAI-compatible model name is {_WORD}, with '/' between parts (org/model) and ':' before a tag "
        "(model:tag)",
    ),
}
_GEMINI_PREFIXES = ("models/", "tunedModels/")


def _show(ch: str) -> str:
    if ch == " ":
        return "' ' (a space)"
    if ch.isprintable():
        return repr(ch)
    return f"U+{ord(ch):04X} ({unicodedata.name(ch, 'a control character')})"


def model_name_problem(planner: str, model: str) -> str | None:
    """Why `model` cannot be a model name for `planner` (naming the first bad character and where it is), or None.
    Planners not listed (offline ones take no model) are not checked here."""
    rule = _RULES.get(planner)
    if rule is None:
        return None
    extra, written = rule
    for i, ch in enumerate(model):
        if not (ch.isascii() and (ch.isalnum() or ch in "._-" or ch in extra)):
            return f"model: {model!r}: character {i + 1}, {_show(ch)}, is not allowed ({written})"
    if ".." in model:
        return f"model: {model!r}: '..' is not allowed ({written})"
    name = model
    if planner == "gemini":
        prefix = next((p for p in _GEMINI_PREFIXES if model.startswith(p)), "")
        name = model[len(prefix) :]
        if "/" in name:
            return (
                f"model: {model!r}: '/' is not allowed past the prefix ({written}): Gemini's URL path holds the "
                "name, and a '/' would name another path"
            )
        parts = [name]
    else:
        if name.count(":") > 1:
            return f"model: {model!r}: ':' appears more than once ({written})"
        base, _, tag = name.partition(":")
        parts = base.split("/") + ([tag] if ":" in name else [])
    bad = next((p for p in parts if not _PART.fullmatch(p)), None)
    if bad is not None:
        what = "an empty part" if bad == "" else f"the part {bad!r}"
        return f"model: {model!r} has {what}: each part of a name starts with a letter or digit ({written})"
    return None
