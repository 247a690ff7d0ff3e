"""Human-readable grammar reference (Markdown and a terminal table), generated from the registry."""

from __future__ import annotations

from .registry import REGISTRY, Registry
from .spec import PrimitiveSpec, SlotSpec, Tier


def _slot_sig(s: SlotSpec) -> str:
    sig = s.name + ("*" if s.required else "")
    if s.default is not None:
        sig += f"={s.default}"
    return sig


def signature(spec: PrimitiveSpec) -> str:
    return f"{spec.name}{{{', '.join(_slot_sig(s) for s in spec.slots)}}}"


def _slot_detail(s: SlotSpec) -> str:
    parts = [s.type.value]
    if s.unit:
        parts.append(s.unit)
    if s.values:
        parts.append("|".join(s.values))
    if s.minimum is not None and s.maximum is not None:
        parts.append(f"[{s.minimum}, {s.maximum}]")
    return f"`{_slot_sig(s)}` ({', '.join(parts)})"


def markdown(registry: Registry = REGISTRY) -> str:
    lines = [
        "# SPARK grammar reference",
        "",
        "Generated from `spark_core/grammar/primitives.yaml` by `spark grammar --format md`; do not edit by hand.",
        "`*` marks a required slot. Positions are world-frame metres; timeouts are simulated seconds.",
        "",
        "Composite nodes: `sequence` (children in order), `parallel` (one arm-tagged branch per arm, joined at an",
        "implicit barrier), `fallback` (children in order until one succeeds).",
        "",
        "A plan is `task:` (one line) and `tree:` (one node). A leaf names its primitive under `type:` and its slots",
        "under `params:`; the arm that runs it, where the primitive takes one, is `arm` inside `params` (or on an",
        "enclosing composite). This is the form the project writes; the older `primitive: <name>` leaf, with `arm`",
        "as a node key, is still read.",
        "",
        "```yaml",
        "task: put the fork down to the left",
        "tree:",
        "  type: sequence",
        "  children:",
        "    - type: pick_with_arm",
        "      params: {arm: left, keypoint_label: fork, force: 30, prefer_angled: true}",
        "    - type: move_relative",
        "      params: {arm: left, dy: 0.1}",
        "    - type: place_with_arm",
        "      params: {arm: left}",
        "```",
        "",
    ]
    for tier in Tier:
        specs = registry.by_tier(tier)
        lines += [
            f"## {tier.value} ({len(specs)})",
            "",
            "| primitive | slots | arm | timeout | post-condition | description |",
            "|---|---|---|---|---|---|",
        ]
        for spec in specs:
            slots = "<br>".join(_slot_detail(s) for s in spec.slots) or "none"
            lines.append(
                f"| `{spec.name}` | {slots} | {spec.arm.value} | {spec.timeout_s:g} s | {spec.postcondition} | "
                f"{spec.description} |"
            )
        lines.append("")
    return "\n".join(lines)


def table(registry: Registry = REGISTRY) -> str:
    width = max(len(s.name) for s in registry)
    return "\n".join(
        f"{spec.tier.value:<9} {spec.name:<{width}} {signature(spec)[len(spec.name) :]:<70} {spec.timeout_s:>4g}s"
        for spec in registry
    )
