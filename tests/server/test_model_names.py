"""Model names are checked against the characters model names are made of (API pass): Gemini puts the name into
its URL's path (`models/{model}:generateContent`), and `gemini-2.5-flash/../../x`, `gemini:streamGenerateContent`
or `a b` were queued (202) as given; an OpenAI-compatible server got any text in its body."""

from __future__ import annotations

from dataclasses import replace

import pytest
from fastapi.testclient import TestClient

from server.app import create_app

from .isolated_settings import isolated_settings


@pytest.fixture()
def client(tmp_path):
    with TestClient(create_app(replace(isolated_settings(tmp_path), workers=0))) as c:
        yield c


@pytest.mark.parametrize(
    "planner,model,named",
    [
        ("gemini", "gemini-2.5-flash/../../files", "'..' is not allowed"),
        ("gemini", "tunedModels/x/../../models/y", "'..' is not allowed"),
        ("gemini", "models/gemini-2.5-pro/other", "'/' is not allowed past the prefix"),
        ("gemini", "gemini-2.5-flash:streamGenerateContent", "character 17, ':', is not allowed"),
        ("gemini", "gemini-2.5-flash?alt=sse", "character 17, '?', is not allowed"),
        ("gemini", "gemini%2F..", "character 7, '%', is not allowed"),
        ("gemini", "gemini#frag", "character 7, '#', is not allowed"),
        ("gemini", "gemini 2.5", "character 7, ' ' (a space), is not allowed"),
        ("gemini", "gemini\u00a02.5", "character 7, U+00A0 (NO-BREAK SPACE), is not allowed"),
        ("gemini", "gémini", "character 2, 'é', is not allowed"),
        ("gemini", "models/", "has an empty part"),
        ("openai", "qwen3 8b", "character 6, ' ' (a space), is not allowed"),
        ("openai", "qwen3:8b:extra", "':' appears more than once"),
        ("openai", "../../etc/passwd", "'..' is not allowed"),
        ("openai", "/qwen3", "has an empty part"),
        ("openai", "org//model", "has an empty part"),
        ("openai", "model\\name", "character 6, '\\\\', is not allowed"),
    ],
)
def test_a_model_name_with_a_character_no_model_name_has_is_a_422_naming_it(client, planner, model, named):
    r = client.post("/api/trials", json={"task": "lift_block", "planner": planner, "model": model})
    assert r.status_code == 422, r.text
    detail = r.json()["detail"]
    assert detail.startswith(f"model: {model!r}") and named in detail, detail
    assert ("Gemini" if planner == "gemini" else "OpenAI-compatible") in detail
    # a batch's model is every trial's: refused the same, nothing queued
    r = client.post("/api/batches", json={"tasks": ["lift_block"], "planner": planner, "model": model})
    assert r.status_code == 422 and named in r.json()["detail"], r.text
    assert client.get("/api/trials").json()["total"] == 0 and client.get("/api/batches").json()["total"] == 0


@pytest.mark.parametrize(
    "planner,model",
    [
        ("gemini", "gemini-2.5-flash"),
        ("gemini", "gemini-3.1-pro-preview"),
        ("gemini", "models/gemini-2.5-pro"),
        ("gemini", "tunedModels/my-model_1"),
        ("openai", "gpt-4.1"),
        ("openai", "qwen3:8b"),
        ("openai", "Qwen/Qwen2.5-VL-7B-Instruct"),
        ("openai", "hf.co/bartowski/Llama-3.2-1B-Instruct-GGUF:Q4_K_M"),
    ],
)
def test_the_model_names_vendors_use_are_taken(client, planner, model):
    r = client.post("/api/trials", json={"task": "lift_block", "planner": planner, "model": model})
    assert r.status_code == 202, r.text
