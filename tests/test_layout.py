"""Dependencies point one way (DESIGN.md): the engine never imports the server, planning never imports
execution, the server uses only the engine's public API, and names come from the one catalog."""

from __future__ import annotations

import ast
import json
import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def _imports(path: Path) -> list[tuple[str, list[str]]]:
    """(module, names) of every import in a file, relative imports resolved against its package."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    package = ".".join(path.relative_to(ROOT).with_suffix("").parts[:-1])
    out = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            out += [(a.name, []) for a in node.names]
        elif isinstance(node, ast.ImportFrom):
            module = node.module or ""
            if node.level:
                base = package.split(".")[: len(package.split(".")) - node.level + 1]
                module = ".".join([*base, module] if module else base)
            out.append((module, [a.name for a in node.names]))
    return out


def _files(package: str) -> list[Path]:
    return sorted((ROOT / package).rglob("*.py"))


def test_the_engine_never_imports_the_server_or_the_cli():
    for path in _files("spark_core"):
        for module, _ in _imports(path):
            assert module.split(".")[0] not in ("server", "spark_cli"), f"{path}: imports {module}"
        text = path.read_text(encoding="utf-8")
        assert not re.search(r"import_module\(\s*f?[\"'](server|spark_cli)", text), (
            f"{path} loads the server dynamically"
        )


def test_planning_and_perception_do_not_import_execution():
    for package in ("spark_core/planning", "spark_core/perception", "spark_core/grammar"):
        for path in _files(package):
            for module, _ in _imports(path):
                assert not module.startswith("spark_core.execution"), f"{path}: imports {module}"


def test_the_server_uses_only_the_engines_public_api():
    import spark_core

    public = set(spark_core.__all__)
    for path in _files("server"):
        for module, names in _imports(path):
            if module.split(".")[0] != "spark_core":
                continue
            assert module == "spark_core", f"{path}: reaches into {module}; import it from spark_core"
            assert set(names) <= public, f"{path}: {set(names) - public} not in spark_core's public API"


def test_every_public_name_resolves():
    import spark_core

    for name in spark_core.__all__:
        assert getattr(spark_core, name) is not None


def test_names_of_planners_segmenters_and_embodiments_are_listed_once():
    """No hand-written list of catalog names outside the catalog (CLI, API models, batches, web sources)."""
    from spark_core.catalog import EMBODIMENTS, PLANNERS, SEGMENTERS

    names = "|".join(re.escape(n) for n in [*PLANNERS, *SEGMENTERS, *EMBODIMENTS])
    # two catalog names side by side in a list, a regex alternation or an <option> run
    pattern = re.compile(rf"""(?<=["'>(])(?:{names})["']?\s*[,|]?\s*(?:</?[^>]*>)*\s*["']?(?:{names})(?=["'<)|])""")
    offenders = []
    for path in [*_files("server"), *_files("spark_cli"), *(ROOT / "web").rglob("*.[jt]s")]:
        if "node_modules" in path.parts or "dist" in path.parts:
            continue
        if pattern.search(path.read_text(encoding="utf-8", errors="replace")):
            offenders.append(str(path.relative_to(ROOT)))
    assert offenders == []


def test_the_api_serves_the_catalog_the_cli_offers(tmp_path):
    from fastapi.testclient import TestClient

    from server.app import create_app
    from server.settings import Settings
    from spark_cli import build_parser
    from spark_core.catalog import catalog_json

    with TestClient(create_app(Settings(store_url=f"sqlite:///{tmp_path / 'c.db'}", workers=1, viser=False))) as c:
        served = c.get("/api/catalog").json()
        bad = c.post("/api/trials", json={"task": "lift_block", "segmenter": "oracle"})
        schema = c.get("/openapi.json").json()["components"]["schemas"]["TrialCreate"]["properties"]
    assert served == json.loads(json.dumps(catalog_json()))
    assert {s["name"]: s["privileged"] for s in served["segmenters"]} == {
        "sim": True,
        "sim-noisy": True,
        "learned": False,
        "sam3": False,
        "privileged-keypoints": True,
    }
    assert served["verdict"] == [
        "success",
        "task_unmet",
        "tree_failed",
        "planner_error",
        "aborted",
        "timeout",
        "interrupted",
        "crashed",
    ]
    assert bad.status_code == 422 and "unknown segmenter 'oracle'" in bad.text
    assert schema["segmenter"]["enum"] == [s["name"] for s in served["segmenters"]]
    run = next(a for a in build_parser()._subparsers._group_actions[0].choices["run"]._actions if a.dest == "segmenter")
    assert list(run.choices) == schema["segmenter"]["enum"]


def test_spark_catalog_lists_every_robot_the_api_accepts(capsys):
    """`spark catalog` (text) names each embodiment the API takes, with its arms and, for a benchmark's own robot,
    the suite it runs (the CaP-Bench and LIBERO-PRO robots were missing from the listing)."""
    from spark_cli import main
    from spark_core.catalog import ALL_EMBODIMENTS

    assert main(["catalog"]) == 0
    listing = capsys.readouterr().out
    for e in ALL_EMBODIMENTS.values():
        line = next(ln for ln in listing.splitlines() if ln.split()[:1] == [e.name])
        assert f"arms: {', '.join(e.arms)}" in line
        assert (f"({e.suite} tasks only)" in line) == bool(e.suite)
    assert {"libero-panda", "robosuite-two-pandas"} <= set(ALL_EMBODIMENTS)
