"""Hostile input is rejected fast with a clear error: never a crash, a hang or an object constructed."""

import time

import pytest

from spark_core.grammar import PlanError, parse_plan

BOMB = """
a: &a ["lol","lol","lol","lol","lol","lol","lol","lol","lol"]
b: &b [*a,*a,*a,*a,*a,*a,*a,*a,*a]
c: &c [*b,*b,*b,*b,*b,*b,*b,*b,*b]
d: &d [*c,*c,*c,*c,*c,*c,*c,*c,*c]
e: &e [*d,*d,*d,*d,*d,*d,*d,*d,*d]
f: &f [*e,*e,*e,*e,*e,*e,*e,*e,*e]
g: &g [*f,*f,*f,*f,*f,*f,*f,*f,*f]
task: x
tree: {primitive: wait}
"""

HOSTILE = [
    ("yaml-alias-bomb", BOMB, "aliases"),
    ("ten-megabytes", "task: x\ntree: {primitive: wait}\n#" + "x" * (10 * 1024 * 1024), "the limit is"),
    ("nesting-10000-json", "[" * 10_000 + "]" * 10_000, "nesting deeper than"),
    ("nesting-10000-yaml-flow", "tree: " + "{a: " * 10_000 + "1" + "}" * 10_000, "nesting deeper than"),
    ("nesting-10000-yaml-block", "tree:\n" + "".join(" " * i + "- \n" for i in range(0, 300)), "nesting deeper than"),
    ("non-utf8", b"task: caf\xe9\ntree: {primitive: wait}\n", "not valid UTF-8: byte 0xe9 at offset 9"),
    ("python-object-tag", "task: !!python/object/apply:os.system ['echo pwned']\ntree: {primitive: wait}", "tag"),
    ("python-name-tag", "task: x\ntree: !!python/name:os.system {}", "tag"),
    ("custom-tag", "task: !secret x\ntree: {primitive: wait}", "tag"),
    ("nul-byte", "task: x\x00\ntree: {primitive: wait}", "NUL character"),
    (
        "deep-valid-tree",
        "task: x\ntree: " + '{"type": "sequence", "children": [' * 28 + '{"primitive": "wait"}' + "]}" * 28,
        "nested deeper than",
    ),
]


@pytest.mark.parametrize("text,fragment", [h[1:] for h in HOSTILE], ids=[h[0] for h in HOSTILE])
def test_hostile_input_rejected_fast(text, fragment):
    t0 = time.perf_counter()
    with pytest.raises(PlanError) as info:
        parse_plan(text)
    elapsed = time.perf_counter() - t0
    assert elapsed < 1.0, f"took {elapsed:.2f} s"
    assert any(fragment in str(i) for i in info.value.issues), info.value.issues


def test_wide_plan_many_nodes_rejected():
    text = (
        '{"task": "x", "tree": {"type": "sequence", "children": [' + ",".join(['{"primitive": "wait"}'] * 3000) + "]}}"
    )
    with pytest.raises(PlanError, match="more than 2000 nodes"):
        parse_plan(text)
