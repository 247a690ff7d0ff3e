"""The `spark` command as a user runs it (a real subprocess)."""

import json
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def spark(*args, stdin=None):
    return subprocess.run(
        [sys.executable, "-m", "spark_cli", *args], cwd=ROOT, capture_output=True, text=True, input=stdin, timeout=120
    )


def test_help_lists_commands():
    out = spark("--help")
    assert out.returncode == 0 and "grammar" in out.stdout and "validate" in out.stdout


def test_validate_examples_ok():
    files = sorted(str(p) for p in (ROOT / "examples/plans").glob("*.yaml"))
    out = spark("validate", *files)
    assert out.returncode == 0, out.stdout + out.stderr
    assert out.stdout.count(": ok - ") == len(files)


def test_validate_lists_every_error_and_exits_1(tmp_path):
    bad = tmp_path / "bad.yaml"
    bad.write_text(
        "task: t\ntree:\n  type: sequence\n  children:\n"
        "    - {primitive: grasp, params: {force: high}}\n    - {primitive: grap}\n"
    )
    out = spark("validate", str(bad))
    assert out.returncode == 1
    assert 'tree.children[0].params.force: expected number in [0, 140], got "high"' in out.stdout
    assert "tree.children[1].primitive: unknown primitive 'grap' (did you mean 'grasp'?)" in out.stdout
    assert "INVALID (2 errors)" in out.stdout


def test_validate_missing_file_and_stdin(tmp_path):
    out = spark("validate", str(tmp_path / "nope.yaml"))
    assert out.returncode == 1 and "cannot read" in out.stderr
    out = spark("validate", "-", stdin="task: t\ntree: {primitive: wait}\n")
    assert out.returncode == 0 and "1 primitive" in out.stdout


def test_grammar_formats():
    schema = json.loads(spark("grammar", "--format", "json-schema").stdout)
    assert "primitive_move_to_keypoint" in schema["$defs"]
    assert spark("grammar", "--format", "md").stdout.startswith("# SPARK grammar reference")
    assert "constrained_scrub" in spark("grammar").stdout
