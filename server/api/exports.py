"""Exports: selected trials (or a batch's) as a LeRobot v3.0 dataset, zipped for download; listed and deleted.

On disk, under SPARK_EXPORTS_DIR, one directory per export: `dataset/` (the LeRobot files), `<id>.zip` (the
download, renamed into place once whole) and then `export.json` (when, what, how many trials). An export is
`writing` while its request runs (known to this server only), `ready` once its zip is in place, and
`incomplete` when a server stopped while writing it (files left behind: delete them).
"""

from __future__ import annotations

import contextlib
import json
import os
import re
import shutil
import uuid
from datetime import UTC, datetime
from pathlib import Path
from typing import Annotated, Literal

from fastapi import APIRouter, HTTPException, Query, Request
from fastapi import Path as PathParam
from fastapi.responses import FileResponse
from pydantic import BaseModel, ConfigDict, Field

from .models import MAX_ID, MAX_OFFSET
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
    # a deleted batch's trials are kept, and still exported by its id
    if body.batch and store.get_batch(body.batch) is None and not store.trial_ids(batch=body.batch):
        raise HTTPException(404, f"no batch {body.batch!r}")
    export_id = f"export-{uuid.uuid4().hex[:10]}"
    root = Path(request.app.state.settings.exports_dir) / export_id
    flt = ExportFilter(trial_ids=tuple(body.trial_ids or ()), batch=body.batch, success_only=body.success_only)
    writing: set[str] = request.app.state.exports_writing
    writing.add(export_id)  # before its first file: a DELETE sees it writing, or no export at all
    try:
        root.mkdir(parents=True)  # listed (as writing) from the start
        try:
            report = export_lerobot(store, root / "dataset", flt)
        except ExportError as e:
            shutil.rmtree(root, ignore_errors=True)
            raise HTTPException(422, _without_paths(str(e))) from None
        # written under another name and renamed: a zip under the export's name is always whole
        part = shutil.make_archive(str(root / f"{export_id}.part"), "zip", root / "dataset")
        os.replace(part, root / f"{export_id}.zip")
        record = {
            "id": export_id,
            "created_at": datetime.now(UTC).isoformat(),
            "trials": report.episodes,
            "frames": report.frames,
            "batch": body.batch,
            "selected": len(body.trial_ids or ()),
            "success_only": body.success_only,
        }
        (root / "export.json").write_text(json.dumps(record))
    finally:
        writing.discard(export_id)
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


_ID = re.compile(r"export-[0-9a-zA-Z]{1,64}")


class ExportSummary(BaseModel):
    id: str
    status: Literal["writing", "ready", "incomplete"]
    created_at: str = Field(description="ISO time (UTC) the export was written")
    trials: int | None = Field(
        ge=0, le=2**31, description="trials in the dataset (one episode each); None until it is written"
    )
    frames: int | None = Field(ge=0, le=2**53, description="frames in the dataset; None until it is written")
    bytes: int = Field(ge=0, le=2**63, description="bytes on disk: the dataset and its zip")
    batch: str | None = Field(None, description="the batch it was made from, if any")
    download: str | None = Field(description="the zip's URL once it is ready")


class ExportPage(BaseModel):
    total: int
    limit: int
    offset: int
    items: list[ExportSummary]


class ExportDeleted(BaseModel):
    id: str
    bytes_freed: int


def _directory(request: Request, export_id: str) -> Path:
    """The export's directory; 404 naming the id when there is none (or the id is not an export's)."""
    path = Path(request.app.state.settings.exports_dir) / export_id
    if not _ID.fullmatch(export_id) or not path.is_dir():
        raise HTTPException(404, f"no export {export_id!r}")
    return path


def _bytes(root: Path) -> int:
    total = 0
    for folder, _dirs, files in os.walk(root):
        for name in files:
            with contextlib.suppress(FileNotFoundError):  # removed while we counted
                total += (Path(folder) / name).stat().st_size
    return total


def _summary(root: Path, writing: set[str]) -> ExportSummary:
    export_id = root.name
    try:
        record = json.loads((root / "export.json").read_text())
    except (OSError, ValueError):
        record = {}
    if export_id in writing:
        status: Literal["writing", "ready", "incomplete"] = "writing"
    else:  # its zip is renamed into place whole, just before its record is written
        status = "ready" if (root / f"{export_id}.zip").is_file() else "incomplete"
    if not record and status == "ready":  # written before export.json was: the dataset says how many
        try:
            info = json.loads((root / "dataset" / "meta" / "info.json").read_text())
            record = {"trials": info.get("total_episodes"), "frames": info.get("total_frames")}
        except (OSError, ValueError):
            pass
    created = record.get("created_at") or datetime.fromtimestamp(root.stat().st_mtime, UTC).isoformat()
    return ExportSummary(
        id=export_id,
        status=status,
        created_at=created,
        trials=record.get("trials"),
        frames=record.get("frames"),
        bytes=_bytes(root),
        batch=record.get("batch"),
        download=f"/api/exports/{export_id}.zip" if status == "ready" else None,
    )


@router.get("", response_model=ExportPage)
def list_exports(
    request: Request, limit: int = Query(100, ge=1, le=500), offset: int = Query(0, ge=0, le=MAX_OFFSET)
) -> ExportPage:
    """Every export on this server, newest first: when, how many trials, its size on disk, its download."""
    root = Path(request.app.state.settings.exports_dir)
    writing = set(request.app.state.exports_writing)
    dirs = [d for d in root.iterdir() if d.is_dir() and _ID.fullmatch(d.name)] if root.is_dir() else []
    items = []
    for d in dirs:
        try:
            items.append(_summary(d, writing))
        except FileNotFoundError:  # deleted while we listed
            continue
    items.sort(key=lambda e: e.created_at, reverse=True)
    return ExportPage(total=len(items), limit=limit, offset=offset, items=items[offset : offset + limit])


@router.delete("/{export_id}", response_model=ExportDeleted)
def delete_export(export_id: Annotated[str, PathParam(max_length=MAX_ID)], request: Request) -> ExportDeleted:
    """Remove the export's files (dataset and zip); it cannot be undone. 409 while it is being written."""
    if export_id in request.app.state.exports_writing:
        raise HTTPException(409, f"export {export_id!r} is still being written: delete it once it is done")
    root = _directory(request, export_id)
    # Out of the listing in one atomic rename before anything is removed: of two deletes at once one gets the
    # export, the other its 404 (both removing the same files answered 500s, and each counted part of the bytes).
    doomed = root.with_name(f".deleting-{export_id}-{uuid.uuid4().hex[:8]}")
    try:
        root.rename(doomed)
    except FileNotFoundError:
        raise HTTPException(404, f"no export {export_id!r}") from None
    freed = _bytes(doomed)
    shutil.rmtree(doomed)
    return ExportDeleted(id=export_id, bytes_freed=freed)


@router.get("/{export_id}.zip")
def download_export(export_id: str, request: Request) -> FileResponse:
    if not _ID.fullmatch(export_id):
        raise HTTPException(404, f"no export {export_id!r}")
    if export_id in request.app.state.exports_writing:  # its zip may be half written
        raise HTTPException(409, f"export {export_id!r} is still being written: download it once it is done")
    path = Path(request.app.state.settings.exports_dir) / export_id / f"{export_id}.zip"
    if not path.exists():
        raise HTTPException(404, f"no export {export_id!r}")
    return FileResponse(path, media_type="application/zip", filename=f"{export_id}-lerobot.zip")
