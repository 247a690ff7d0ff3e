"""Exports: selected trials (or a batch's) as a LeRobot v3.0 dataset, zipped for download."""

from __future__ import annotations

import re
import shutil
import uuid
from pathlib import Path
from typing import Annotated

from fastapi import APIRouter, HTTPException, Request
from fastapi.responses import FileResponse
from pydantic import BaseModel, ConfigDict, Field

from .models import MAX_ID
from .text import VISIBLE

router = APIRouter(prefix="/api/exports", tags=["exports"])


class ExportCreate(BaseModel):
    model_config = ConfigDict(extra="forbid")  # a misspelt field is an error, not ignored

    trial_ids: list[Annotated[str, Field(max_length=MAX_ID), VISIBLE]] | None = Field(
        None, max_length=5000, description="these trials (history selection)"
    )
    batch: Annotated[str, Field(max_length=64), VISIBLE] | None = Field(
        None, description="or every trial of this batch"
    )
    success_only: bool = Field(True, strict=True, description="verified successes only (clean demonstrations)")
    format: str = Field("lerobot", pattern="^lerobot$")


@router.post("", status_code=201)
def create_export(body: ExportCreate, request: Request) -> dict:
    from spark_core import ExportError, ExportFilter, export_lerobot

    if not body.trial_ids and not body.batch:
        raise HTTPException(422, "say what to export: trial_ids (a selection) or batch")
    store = request.app.state.store
    if body.trial_ids:  # a selection names trials that exist: a typo is an error, not a smaller dataset
        known = set(store.trial_ids(ids=body.trial_ids))
        unknown = list(dict.fromkeys(i for i in body.trial_ids if i not in known))
        if unknown:
            raise HTTPException(
                404,
                f"no trial {', '.join(map(repr, unknown[:20]))}"
                + (f" (and {len(unknown) - 20} more)" if len(unknown) > 20 else ""),
            )
    if body.batch and store.get_batch(body.batch) is None:
        raise HTTPException(404, f"no batch {body.batch!r}")
    export_id = f"export-{uuid.uuid4().hex[:10]}"
    root = Path(request.app.state.settings.exports_dir) / export_id
    flt = ExportFilter(trial_ids=tuple(body.trial_ids or ()), batch=body.batch, success_only=body.success_only)
    try:
        report = export_lerobot(store, root / "dataset", flt)
    except ExportError as e:
        shutil.rmtree(root, ignore_errors=True)
        raise HTTPException(422, _without_paths(str(e))) from None
    shutil.make_archive(str(root / export_id), "zip", root / "dataset")
    # Where the server keeps files is its own business: the client gets the download URL, never a path.
    return {
        "id": export_id,
        "episodes": report.episodes,
        "frames": report.frames,
        "bytes": report.bytes_on_disk,
        "skipped": [{**s, "reason": _without_paths(str(s.get("reason", "")))} for s in report.skipped],
        "wall_time_s": report.wall_time_s,
        "download": f"/api/exports/{export_id}.zip",
    }


_PATH = re.compile(r"(?<![\w.:/])/(?:[^\s'\"/]+/)+([^\s'\"/]+)")


def _without_paths(text: str) -> str:
    """Absolute file paths in a message reduced to their file names."""
    return _PATH.sub(r"\1", text)


@router.get("/{export_id}.zip")
def download_export(export_id: str, request: Request) -> FileResponse:
    if not export_id.startswith("export-") or not export_id[7:].isalnum():
        raise HTTPException(404, f"no export {export_id!r}")
    path = Path(request.app.state.settings.exports_dir) / export_id / f"{export_id}.zip"
    if not path.exists():
        raise HTTPException(404, f"no export {export_id!r}")
    return FileResponse(path, media_type="application/zip", filename=f"{export_id}-lerobot.zip")
