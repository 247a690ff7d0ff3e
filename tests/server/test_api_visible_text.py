"""Labels, instructions, plans and names with bidi controls or other invisible characters are refused with a 422
naming the field, the character and where it is: the console would show a different text than the one that runs
(adversarial review L10)."""

from __future__ import annotations

import pytest
from fastapi.testclient import TestClient

from server.api.text import hidden_character
from server.app import create_app

from .isolated_settings import isolated_settings

PLAN = "task: lift\ntree:\n  type: pick\n  params: {keypoint_label: red block}\n"


@pytest.fixture(scope="module")
def client(tmp_path_factory):
    with TestClient(create_app(isolated_settings(tmp_path_factory.mktemp("text")))) as c:
        yield c


@pytest.mark.parametrize(
    "url,body,field,char",
    [
        ("/api/trials", {"task": "lift_block", "instruction": "lift the \u202eeulb block"}, "instruction", "U+202E"),
        ("/api/trials", {"task": "lift_block", "plan": PLAN.replace("red", "r\u2067ed")}, "plan", "U+2067"),
        ("/api/trials", {"task": "lift_block", "breakpoints": ["tree\u200b"]}, "breakpoints.0", "U+200B"),
        ("/api/trials", {"task": "lift_block", "planner": "openai", "model": "gpt\u2060x"}, "model", "U+2060"),
        ("/api/trials", {"task": "lift_block\u202a"}, "task", "U+202A"),
        (
            "/api/batches",
            {"specs": [{"task": "lift_block", "instruction": "a\u2066b"}]},
            "specs.0.instruction",
            "U+2066",
        ),
        ("/api/batches", {"tasks": ["lift_block\u00ad"]}, "tasks.0", "U+00AD"),
        ("/api/exports", {"trial_ids": ["a\x1b[2Jb"]}, "trial_ids.0", "U+001B"),
        ("/api/exports", {"batch": "b\ufeffx"}, "batch", "U+FEFF"),
        ("/api/plans/validate", {"text": PLAN.replace("block", "bl\u202dock")}, "text", "U+202D"),
    ],
)
def test_invisible_characters_are_refused_naming_the_field(client, url, body, field, char):
    r = client.post(url, json=body)
    assert r.status_code == 422, r.text
    (error,) = r.json()["detail"]
    assert error["field"] == field and error["type"] == "invisible_character"
    assert char in error["msg"] and "invisible character" in error["msg"]
    assert client.get("/api/trials").json()["total"] == 0  # nothing was queued


def test_the_place_of_the_character_is_named():
    assert hidden_character("plain text, tabs\tand\nnew lines\r\n") is None
    assert hidden_character("ab\u202ecd").startswith("character 3: invisible character U+202E (RIGHT-TO-LEFT")
    assert hidden_character(PLAN.replace("red", "r\u200ded")).startswith("line 4, column 29: ")  # ZERO WIDTH JOINER
    assert hidden_character("\ufeff" + PLAN, leading_bom=True) is None  # a pasted file's byte-order mark
    assert hidden_character("\ufeff" + PLAN) is not None


def test_visible_text_in_other_scripts_is_accepted(client):
    r = client.post("/api/plans/validate", json={"text": PLAN.replace("red block", "عربي 红色方块 κόκκινο")})
    assert r.status_code == 200 and r.json()["ok"] is True
    r = client.post("/api/plans/validate", json={"text": "\ufeff" + PLAN})
    assert r.status_code == 200 and r.json()["ok"] is True
