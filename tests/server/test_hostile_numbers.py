"""Input that pydantic refuses but Python's json cannot echo back (NaN, Infinity, 1e400, lone surrogates), and
integers too long for Python to convert: a 422 naming the field, never a 500 (adversarial review H1)."""

from __future__ import annotations

import pytest
from fastapi.testclient import TestClient

from server.app import create_app
from server.settings import Settings
from spark_core import validate

JSON = {"content-type": "application/json"}


@pytest.fixture(scope="module")
def client(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("h1")
    settings = Settings(store_url=f"sqlite:///{tmp / 'h.db'}", workers=1, viser=False, artifacts_dir=str(tmp / "a"))
    with TestClient(create_app(settings), raise_server_exceptions=False) as c:
        yield c


@pytest.mark.parametrize(
    "url,body,field",
    [
        ("/api/trials", '{"task":"lift_block","time_limit_s":NaN}', "time_limit_s"),
        ("/api/trials", '{"task":"lift_block","time_limit_s":Infinity}', "time_limit_s"),
        ("/api/trials", '{"task":"lift_block","pacing":1e400}', "pacing"),
        ("/api/batches", '{"trials":NaN}', "trials"),
        ("/api/trials", '{"task":"\\ud800", "seed": "x"}', "seed"),
        ("/api/trials", '{"task":"lift_block","\\ud800":1}', ""),  # pydantic refuses the whole body
        ("/api/plans/validate", '{"text":5, "x":"\\udfff"}', "text"),
    ],
)
def test_unserialisable_input_gets_a_422_naming_the_field(client, url, body, field):
    r = client.post(url, content=body.encode(), headers=JSON)
    assert r.status_code == 422, r.text
    fields = [".".join(str(p) for p in d["loc"][1:]) for d in r.json()["detail"]]
    assert field in fields
    assert all("input" not in d for d in r.json()["detail"])
    if field == "":
        assert "lone surrogate" in r.json()["detail"][0]["msg"]


def test_a_non_finite_number_is_called_what_it_is(client):
    r = client.post("/api/trials", content=b'{"task":"lift_block","time_limit_s":NaN}', headers=JSON)
    (d,) = r.json()["detail"]
    assert d["field"] == "time_limit_s" and "finite number" in d["msg"]


@pytest.mark.parametrize("value", ["nan", "NaN", "inf", "-Infinity", "1e400"])
def test_a_non_finite_number_in_a_query_is_called_what_it_is(client, value):
    """A query's number arrives as text: "nan" failed its bounds as a number (t_sim_s=nan: "Input should be less
    than or equal to 1000000", speed=nan the same), not as what it is."""
    for method, url, field in (
        ("GET", f"/api/trials/t/camera.png?t_sim_s={value}", "t_sim_s"),
        ("POST", f"/api/trials/t/replay?speed={value}", "speed"),
    ):
        r = client.request(method, url)
        assert r.status_code == 422, r.text
        (d,) = r.json()["detail"]
        assert d["field"] == field and "finite number" in d["msg"], d
    r = client.post("/api/exports", json={"batch": "x", "format": "nan"})  # text that is not a number stays text
    assert r.status_code == 422 and "finite" not in r.text and "lerobot" in r.text


LONG = "1" + "0" * 5000


@pytest.mark.parametrize(
    "text,path",
    [
        (
            f"task: x\ntree:\n  type: pick\n  params: {{keypoint_label: a, lift_height: {LONG}}}\n",
            "tree.params.lift_height",
        ),
        (f'{{"task":"x","tree":{{"type":"grasp","params":{{"force":{LONG}}}}}}}', "tree.params.force"),
        (
            f"task: x\ntree:\n  type: sequence\n  children: [{{type: wait, params: {{s: 0x{'f' * 5000}}}}}]\n",
            "tree.children[0].params.s",
        ),
    ],
)
def test_an_integer_longer_than_python_converts_is_a_plan_error_at_its_path(client, text, path):
    plan, issues = validate(text)
    assert plan is None and [i.path for i in issues] == [path] and "number too large" in issues[0].message
    r = client.post("/api/plans/validate", json={"text": text})
    assert r.status_code == 200 and r.json()["errors"][0]["path"] == path
    r = client.post("/api/trials", json={"task": "lift_block", "plan": text})
    assert r.status_code == 422 and path in r.json()["detail"]
