// Every trial, paged and sorted by the server; filters by status, verdict, task text and training data; pick two
// to compare, or any to export as a LeRobot dataset.
import { useEffect, useState } from "react";
import { api } from "../api/client";
import { useCatalog } from "../api/catalog";
import type { Page, TrialSummary } from "../api/types";
import { ExportButton } from "../components/ExportButton";
import { TrialTable } from "../components/TrialTable";
import { go } from "../lib/route";

const PAGE = 50;

export function History() {
  const cat = useCatalog();
  const [filters, setFilters] = useState({ q: "", status: "", verdict: "", training: "" });
  const [sort, setSort] = useState("-created_at");
  const [offset, setOffset] = useState(0);
  const [page, setPage] = useState<Page<TrialSummary> | null>(null);
  const [error, setError] = useState("");
  const [picked, setPicked] = useState<Set<string>>(new Set());
  useEffect(() => {
    const q = new URLSearchParams({ limit: String(PAGE), offset: String(offset), sort });
    for (const [k, v] of Object.entries(filters)) if (v) q.set(k, v);
    api<Page<TrialSummary>>(`/api/trials?${q}`).then((p) => { setPage(p); setError(""); }).catch((e) => setError(e.message));
  }, [filters, sort, offset]);
  const set = (k: string, v: string) => { setOffset(0); setFilters({ ...filters, [k]: v }); };
  const pick = (id: string, on: boolean) => { const n = new Set(picked); if (on) n.add(id); else n.delete(id); setPicked(n); };
  const ids = [...picked];
  return (
    <section><h3>History</h3>
      <div className="filters" id="filters">
        <input type="search" name="q" placeholder="task, instruction or reason contains…" value={filters.q} onChange={(e) => set("q", e.target.value)} />
        <label>Status <select name="status" value={filters.status} onChange={(e) => set("status", e.target.value)}>
          <option value="">any</option>{["queued", "running", "done", "interrupted"].map((s) => <option key={s}>{s}</option>)}</select></label>
        <label title="recorded with capture on: frames a LeRobot export takes">Training data <select name="training" value={filters.training} onChange={(e) => set("training", e.target.value)}>
          <option value="">any</option><option value="true">with</option><option value="false">without</option></select></label>
        <span className="verdict-filters" id="verdict-filters">verdict:
          <button className={!filters.verdict ? "chosen" : ""} onClick={() => set("verdict", "")}>any</button>
          {(cat?.verdict ?? []).map((v) => <button key={v} data-verdict={v} className={filters.verdict === v ? "chosen" : ""} onClick={() => set("verdict", v)}>{v}</button>)}
        </span>
      </div>
      <div className="actions">
        <button id="compare" disabled={ids.length !== 2} onClick={() => go(`#/compare/${encodeURIComponent(ids[0])}/${encodeURIComponent(ids[1])}`)}>Compare the two picked</button>
        <ExportButton body={{ trial_ids: ids }} disabled={!ids.length} label="Export picked (LeRobot)" />
      </div>
      {error && <p className="fail">{error}</p>}
      {page && (
        <div id="rows">
          <p id="page-info">{page.total} trial(s) · {page.total ? offset + 1 : 0}–{offset + page.items.length}
            <button id="prev" disabled={offset === 0} onClick={() => setOffset(Math.max(0, offset - PAGE))}>‹ previous</button>
            <button id="next" disabled={offset + PAGE >= page.total} onClick={() => setOffset(offset + PAGE)}>next ›</button></p>
          <TrialTable items={page.items} sort={sort} onSort={(s) => { setOffset(0); setSort(s); }} picked={picked} onPick={pick} />
        </div>
      )}
    </section>
  );
}
