// Every batch, newest first, with its settings and progress.
import { useEffect, useState } from "react";
import { api } from "../api/client";
import type { BatchSummary, Page } from "../api/types";
import { localTime } from "../lib/localTime";

export const settingsOf = (spec: Record<string, unknown>) =>
  ["suite", "planner", "model", "endpoint", "segmenter", "trials", "seed", "capture"]
    .filter((k) => spec[k] !== null && spec[k] !== undefined && spec[k] !== false)
    .map((k) => `${k} ${String(spec[k])}`).join(" · ");

export function Batches() {
  const [page, setPage] = useState<Page<BatchSummary> | null>(null);
  const [error, setError] = useState("");
  useEffect(() => { api<Page<BatchSummary>>("/api/batches?limit=200").then(setPage).catch((e) => setError(e.message)); }, []);
  if (error) return <section className="fail">{error}</section>;
  if (!page) return <section>loading…</section>;
  return (
    <section><h3>Batches <span className="muted">({page.total})</span></h3>
      <table id="batch-list"><thead><tr><th>batch</th><th>created</th><th>settings</th><th>status</th><th>progress</th><th>successes</th></tr></thead>
        <tbody>{page.items.map((b) => (
          <tr key={b.id} data-id={b.id}><td><a href={`#/batch/${b.id}`}>{b.id}</a></td><td className="created">{localTime(b.created_at)}</td><td>{settingsOf(b.spec)}</td>
            <td>{b.status}</td><td><progress max={b.progress.total} value={b.progress.done} /> {b.progress.done} / {b.progress.total}</td>
            <td>{b.progress.successes ?? ""}</td></tr>))}</tbody></table>
    </section>
  );
}
