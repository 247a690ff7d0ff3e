"""Console settings for a test: its own store, artifacts and exports under the test's tmp_path, one worker, no
3D view; keyword arguments override (api_token, host, ...). Test-only."""

from __future__ import annotations

from server.settings import Settings


def isolated_settings(tmp_path, **kw) -> Settings:
    return Settings(
        store_url=f"sqlite:///{tmp_path / 's.db'}",
        workers=1,
        viser=False,
        artifacts_dir=str(tmp_path / "art"),
        exports_dir=str(tmp_path / "exports"),
        **kw,
    )
