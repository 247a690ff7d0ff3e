"""Planner cost per call from a price table (USD per 1M tokens; reasoning tokens bill as output)."""

from __future__ import annotations

from .protocol import Usage

# model -> (input, output) USD per 1M tokens. The paper's rates for Gemini 3.1 Pro.
PRICES_USD_PER_MTOK: dict[str, tuple[float, float]] = {
    "gemini-3.1-pro-preview": (2.00, 12.00),
    "gemini-3.1-pro": (2.00, 12.00),
}


def cost_usd(model: str, usage: Usage, prices: dict[str, tuple[float, float]] | None = None) -> float:
    """0.0 for models without a price (local servers)."""
    table = PRICES_USD_PER_MTOK if prices is None else prices
    rate = table.get(model)
    if rate is None:
        return 0.0
    return (usage.input_tokens * rate[0] + (usage.output_tokens + usage.reasoning_tokens) * rate[1]) / 1e6
