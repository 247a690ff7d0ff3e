"""A batch created through the console API stores its manifest (code, packages, task files, seeds, settings)."""

from fastapi.testclient import TestClient

from server.app import create_app
from server.settings import Settings


def test_console_batch_stores_its_manifest(tmp_path):
    app = create_app(Settings(store_url=f"sqlite:///{tmp_path / 'api.db'}", workers=1, artifacts_dir=str(tmp_path)))
    with TestClient(app) as client:
        created = client.post(
            "/api/batches",
            json={"tasks": ["lift_block", "push_to_zone"], "trials": 2, "seed": 5, "segmenter": "privileged-keypoints"},
        ).json()
        batch = client.get(f"/api/batches/{created['id']}").json()
        client.post(f"/api/batches/{created['id']}/cancel")
    m = batch["spec"]["manifest"]
    assert m["id"] == created["manifest_id"] and m["batch_id"] == created["id"]
    assert m["run"]["tasks"] == ["lift_block", "push_to_zone"] and m["run"]["seeds"] == [5, 6]
    assert m["run"]["seeds_per_task"] == {"lift_block": [5, 6], "push_to_zone": [5, 6]}
    assert m["run"]["segmenter"]["privileged"] is True and m["run"]["executor"]["name"] == "console"
    assert len(m["environment"]["git"]["commit"]) == 40 and m["environment"]["packages"]["mujoco"]
    assert "spark_core/sim/tasks/reference/lift_block.yaml" in m["files"]
