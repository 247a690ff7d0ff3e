"""422 answers for request bodies and queries pydantic refused, safe to serialise whatever the caller sent.

FastAPI's default handler echoes each error's `input` (and `ctx`) back; a NaN, an Infinity, a 1e400 or a lone
surrogate in the body then makes the answer itself unserialisable, and the caller got a 500 and a dropped
connection. This one keeps FastAPI's shape (`{"detail": [{"type", "loc", "msg"}]}`, which the web client reads)
but never echoes the input, and escapes anything in `loc`/`msg` that JSON or UTF-8 cannot carry.
"""

from __future__ import annotations

import math
from typing import Any

from fastapi import FastAPI, Request
from fastapi.exceptions import RequestValidationError
from fastapi.responses import JSONResponse

# pydantic's messages for a non-finite float ("Input should be a finite number") say nothing about 1e400, which
# JSON parses as inf: name what is expected instead.
_FINITE = "expected a finite number (NaN, Infinity and values beyond ±1.8e308 are not numbers here)"


def _text(value: Any) -> str:
    """A str that UTF-8 can encode: lone surrogates become \\udXXX escapes."""
    return str(value).encode("utf-8", "backslashreplace").decode("utf-8")


def _loc_part(part: Any) -> str | int:
    return part if isinstance(part, int) and not isinstance(part, bool) else _text(part)


def _is_non_finite(value: Any) -> bool:
    """A NaN or infinite float, or the query or path text of one ("nan", "inf", "1e400"): a query's number
    arrives as text and failed its bounds as a number ("t_sim_s=nan: less than or equal to 1000000")."""
    if isinstance(value, str) and len(value) <= 400:
        try:
            value = float(value)
        except ValueError:
            return False
    return isinstance(value, float) and not math.isfinite(value)


_BOUNDS = frozenset({"greater_than", "greater_than_equal", "less_than", "less_than_equal", "finite_number"})


def safe_errors(errors: Any) -> list[dict[str, Any]]:
    out = []
    for e in errors:
        loc = [_loc_part(p) for p in e.get("loc", ())]
        kind = str(e.get("type", ""))
        numeric = not kind.endswith("_type") or kind in ("float_type", "finite_number")
        value = e.get("input")
        if isinstance(value, str) and kind not in _BOUNDS:  # text that fails as text ("nan" for a pattern) is text
            numeric = False
        msg = _FINITE if numeric and _is_non_finite(value) else _text(e.get("msg", "invalid value"))
        if kind == "value_error" and msg.startswith("Value error, "):  # pydantic's prefix on a validator's message
            msg = msg[len("Value error, ") :]
        if kind == "string_unicode":
            msg = "not valid Unicode text: a lone surrogate (\\ud800-\\udfff) is not a character"
        field = ".".join(str(p) for p in loc[1:] if p != "body") if len(loc) > 1 else ""
        entry: dict[str, Any] = {"type": _text(e.get("type", "value_error")), "loc": loc, "msg": msg}
        if field:
            entry["field"] = field
        out.append(entry)
    return out


async def _validation_error(request: Request, exc: Exception) -> JSONResponse:
    assert isinstance(exc, RequestValidationError)
    return JSONResponse({"detail": safe_errors(exc.errors())}, status_code=422)


def install_validation_handler(app: FastAPI) -> None:
    app.add_exception_handler(RequestValidationError, _validation_error)
