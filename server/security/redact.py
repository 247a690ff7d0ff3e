"""No credential in any log line: token query parameters, Authorization values and session cookies are
replaced by `[redacted]` before a handler formats the record (uvicorn's access and error logs included)."""

from __future__ import annotations

import logging
import re

_PATTERNS = [  # order matters: `Bearer x` before `authorization: ...`, so no part of a value survives
    (re.compile(r"(?i)([?&;](?:token|access_token|api_key|apikey|key|password|secret)=)[^&\s\"']*"), r"\1[redacted]"),
    (re.compile(r"(?i)\b(bearer|basic)\s+[A-Za-z0-9._~+/=-]+"), r"\1 [redacted]"),
    (
        re.compile(r"(?i)\b(authorization|x-goog-api-key|x-api-key|api-key|cookie)([\"']?\s*[:=]\s*[\"']?)[^\s\"',}]+"),
        r"\1\2[redacted]",
    ),
    (re.compile(r"spark_session=[^;\s\"',]+"), "spark_session=[redacted]"),
]
LOGGERS = ("uvicorn", "uvicorn.access", "uvicorn.error", "httpx", "httpcore", "websockets")


def redact(text: str) -> str:
    for pattern, replacement in _PATTERNS:
        text = pattern.sub(replacement, text)
    return text


class RedactCredentials(logging.Filter):
    """Rewrites the record's message and string arguments in place (the access formatter unpacks its args)."""

    def filter(self, record: logging.LogRecord) -> bool:
        if isinstance(record.msg, str):
            record.msg = redact(record.msg)
        if isinstance(record.args, tuple):
            record.args = tuple(redact(a) if isinstance(a, str) else a for a in record.args)
        elif isinstance(record.args, dict):
            record.args = {k: redact(v) if isinstance(v, str) else v for k, v in record.args.items()}
        return True


def install_log_redaction(loggers: tuple[str, ...] = LOGGERS) -> None:
    """Idempotent. Logger filters survive uvicorn's logging dictConfig (it replaces handlers, not filters)."""
    for name in loggers:
        logger = logging.getLogger(name)
        if not any(isinstance(f, RedactCredentials) for f in logger.filters):
            logger.addFilter(RedactCredentials())
