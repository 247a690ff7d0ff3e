"""Benchmark reports: Wilson intervals, Markdown tables, and replacing one section of BENCHMARKS.md."""

from __future__ import annotations

import math
import platform
import re
from datetime import date
from pathlib import Path


def wilson(successes: int, n: int, z: float = 1.96) -> tuple[float, float]:
    """95 % Wilson score interval of a success rate."""
    if n == 0:
        return 0.0, 0.0
    p = successes / n
    denom = 1 + z * z / n
    centre = (p + z * z / (2 * n)) / denom
    half = z * math.sqrt(p * (1 - p) / n + z * z / (4 * n * n)) / denom
    return max(0.0, centre - half), min(1.0, centre + half)


def pct(x: float) -> str:
    return f"{100 * x:.1f} %"


def machine() -> str:
    import os

    mem = ""
    try:
        with open("/proc/meminfo") as meminfo:
            kb = int(next(line for line in meminfo if line.startswith("MemTotal")).split()[1])
        mem = f", {kb / 1024 / 1024:.0f} GB RAM"
    except (OSError, StopIteration, ValueError):
        pass
    gpu = "NVIDIA GPU present" if os.path.exists("/proc/driver/nvidia/version") else "no GPU"
    return f"{platform.machine()}, {os.cpu_count()} CPU cores{mem}, {gpu}, Python {platform.python_version()}"


def write_section(path: Path, title: str, body: str) -> None:
    """Replace (or append) the `## title` section of a Markdown file; other sections are left untouched."""
    text = (
        path.read_text()
        if path.exists()
        else "# Benchmarks\n\nEvery figure here is written by the command shown under it.\n"
    )
    section = f"## {title}\n\n{body.strip()}\n"
    pattern = re.compile(rf"^## {re.escape(title)}\n.*?(?=^## |\Z)", re.S | re.M)
    if pattern.search(text):
        text = pattern.sub(lambda _: section + "\n", text).rstrip() + "\n"
    else:
        text = text.rstrip() + "\n\n" + section
    path.write_text(text)


def footer(command: str, protocol: str) -> str:
    return f"Command: `{command}`  \nDate: {date.today().isoformat()}  \nMachine: {machine()}  \nProtocol: {protocol}\n"
