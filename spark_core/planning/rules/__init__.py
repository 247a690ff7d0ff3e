"""`rules`: the offline deterministic planner (instruction parsing, phrase grounding, tree composition)."""

from .parse import Clause, ParseError, parse_instruction
from .planner import RulesPlanner

__all__ = ["Clause", "ParseError", "RulesPlanner", "parse_instruction"]
