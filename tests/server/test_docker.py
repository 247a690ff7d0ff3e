"""No Docker engine runs here: check the image and compose file against the server's own settings instead."""

from pathlib import Path

import yaml

from server.settings import Settings

ROOT = Path(__file__).resolve().parents[2]


def test_compose_matches_server_settings():
    compose = yaml.safe_load((ROOT / "docker/compose.yaml").read_text())
    services = compose["services"]
    assert {"server", "ray-head", "ray-worker", "postgres"} <= set(services)
    server = services["server"]
    env = server["environment"]
    assert f"{Settings.port}:{env['SPARK_PORT']}" in server["ports"] and int(env["SPARK_PORT"]) == Settings.port
    settings_keys = {"SPARK_HOST", "SPARK_PORT", "SPARK_STORE_URL", "SPARK_WORKERS", "SPARK_API_TOKEN"}
    assert settings_keys <= set(env)
    assert env["SPARK_HOST"] == "0.0.0.0" and "SPARK_API_TOKEN:?" in env["SPARK_API_TOKEN"]  # token is mandatory
    assert env["SPARK_STORE_URL"].startswith("sqlite:///")
    assert services["postgres"]["profiles"] == ["postgres"]


def test_image_installs_through_the_readme_install():
    text = (ROOT / "docker/Dockerfile").read_text()
    assert "RUN make install" in text and "FROM python:3.11" in text
    assert '".venv/bin/spark", "serve"' in text and "EXPOSE 8000" in text


def test_settings_read_the_environment(monkeypatch):
    monkeypatch.setenv("SPARK_HOST", "0.0.0.0")
    monkeypatch.setenv("SPARK_PORT", "9000")
    monkeypatch.setenv("SPARK_API_TOKEN", "t")
    s = Settings.from_env()
    assert (s.host, s.port, s.api_token, s.loopback) == ("0.0.0.0", 9000, "t", False)
