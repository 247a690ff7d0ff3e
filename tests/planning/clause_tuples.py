"""The rules planner's clauses as (action, object, relation, target) tuples: what the rules tests compare."""

from spark_core.planning.rules import parse_instruction


def clauses(text: str) -> list[tuple]:
    return [(c.action, c.obj, c.relation, c.target) for c in parse_instruction(text)]
