"""Issue 20, finding 4: every integer and float the API takes is bounded in its schema: out of range is a 422
naming the field, never a 500 (an offset of 10**20 used to overflow SQLite's 64-bit integers)."""

import pytest
from fastapi.testclient import TestClient

from server.app import create_app
from server.settings import Settings


@pytest.fixture(scope="module")
def client(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("bounds")
    settings = Settings(store_url=f"sqlite:///{tmp / 'b.db'}", workers=1, viser=False, artifacts_dir=str(tmp / "art"))
    with TestClient(create_app(settings)) as c:
        yield c


@pytest.mark.parametrize("offset", [10**20, 2**63, 10**9 + 1, -1])
def test_an_offset_out_of_range_is_422_not_500(client, offset):
    r = client.get("/api/trials", params={"offset": offset})
    assert r.status_code == 422 and r.json()["detail"][0]["loc"] == ["query", "offset"], r.text
    assert client.get("/api/trials", params={"offset": 10**9}).json()["items"] == []  # the bound itself pages


@pytest.mark.parametrize(
    ("method", "path", "kw", "field"),
    [
        ("post", "/api/trials", {"json": {"task": "lift_block", "seed": 10**30}}, "seed"),
        ("post", "/api/trials", {"json": {"task": "lift_block", "time_limit_s": 1e308}}, "time_limit_s"),
        ("post", "/api/trials", {"json": {"task": "lift_block", "pacing": 0}}, "pacing"),
        ("post", "/api/trials/x/replay", {"params": {"speed": 1e300}}, "speed"),
        ("get", "/api/trials", {"params": {"limit": 10**20}}, "limit"),
        ("get", "/api/trials", {"params": {"task": "t" * 10_000}}, "task"),
        ("post", "/api/batches", {"json": {"trials": 10**20}}, "trials"),
        ("post", "/api/batches", {"json": {"seed": 2**63}}, "seed"),
        ("get", "/api/trials/" + "x" * 1000, {}, "trial_id"),
    ],
)
def test_numbers_and_strings_past_their_bounds_are_422(client, method, path, kw, field):
    r = getattr(client, method)(path, **kw)
    assert r.status_code == 422, r.text
    assert field in [e["loc"][-1] for e in r.json()["detail"]], r.text


def test_every_number_in_the_schema_has_both_bounds(client):
    """The audit, kept: a new integer or float field without `le=`/`ge=` fails here, before a fuzzer (which
    rarely draws 10**20) or an attacker finds the overflow."""
    spec = client.get("/openapi.json").json()
    components = spec["components"]["schemas"]
    unbounded: list[str] = []

    def visit(where: str, node: dict) -> None:
        if "$ref" in node:
            return  # components are visited on their own
        for key in ("anyOf", "oneOf", "allOf"):
            for k, sub in enumerate(node.get(key, [])):
                visit(f"{where}.{key}[{k}]", sub)
        bounded = {"maximum", "exclusiveMaximum"} & set(node) and {"minimum", "exclusiveMinimum"} & set(node)
        if node.get("type") in ("integer", "number") and not bounded:
            unbounded.append(where)
        for name, prop in node.get("properties", {}).items():
            visit(f"{where}.{name}", prop)
        if isinstance(node.get("items"), dict):
            visit(f"{where}[]", node["items"])

    for name, component in components.items():
        if not name.startswith(("Trial", "Batch", "Export", "Control", "Plan")) or name.endswith(
            ("Page", "Created", "Deleted", "Restored", "Validation")
        ):
            continue  # responses: numbers the server writes
        visit(name, component)
    for path, item in spec["paths"].items():
        for method, op in item.items():
            for param in op.get("parameters", []):
                visit(f"{method.upper()} {path} {param['name']}", param["schema"])
    assert not unbounded, unbounded
    assert len(components) > 5  # the walk saw the schema
