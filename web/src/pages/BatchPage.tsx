// One batch: settings, progress, per-task success with its 95 % interval (a chart and a table), every trial
// linked; cancel only while it runs, export only once something succeeded.
import { useEffect, useState } from "react";
import { api, post } from "../api/client";
import type { Batch } from "../api/types";
import { ExportButton } from "../components/ExportButton";
import { SuccessChart } from "../components/SuccessChart";
import { PhaseChart, type PhaseRow, TimingChart, type TimingRow } from "../components/TimingChart";
import { TrialTable } from "../components/TrialTable";
import { localTime } from "../lib/localTime";
import { settingsOf } from "./Batches";

// no judged trial yet: no rate and no interval, shown as a dash (not 0 %)
const pct = (x: number | null) => (x === null ? "–" : `${(100 * x).toFixed(1)} %`);
const interval = (ci: [number, number] | null) => (ci === null ? "–" : `${pct(ci[0])} – ${pct(ci[1])}`);

export function BatchPage({ id }: { id: string }) {
  const [b, setB] = useState<Batch | null>(null);
  const [error, setError] = useState("");
  const [timing, setTiming] = useState<TimingRow[]>([]);
  const [phases, setPhases] = useState<PhaseRow[]>([]);
  const [reload, setReload] = useState(0); // bumped by Cancel: poll again until its trials have settled
  useEffect(() => {
    let alive = true;
    let timer = 0;
    const load = async () => {
      try {
        const x = await api<Batch>(`/api/batches/${encodeURIComponent(id)}`);
        if (!alive) return;
        setB(x);
        const t = await api<{ rows: TimingRow[]; phases: PhaseRow[] }>(`/api/batches/${encodeURIComponent(id)}/timing`);
        if (alive) { setTiming(t.rows); setPhases(t.phases); }
        // a cancelled batch's running trials are still being aborted: keep polling until each has its verdict
        const unsettled = x.trials.some((t) => t.status === "queued" || t.status === "running");
        if (x.status === "running" || unsettled) timer = window.setTimeout(load, 1000);
      } catch (e) { if (alive) setError((e as Error).message); }
    };
    load();
    return () => { alive = false; clearTimeout(timer); };
  }, [id, reload]);
  if (error && !b) return <section className="fail">{error}</section>;
  if (!b) return <section>loading…</section>;
  const running = b.status === "running";
  const successes = b.results.reduce((s, r) => s + r.successes, 0);
  return (
    <div>
      <section><h3>Batch {b.id}</h3>
        <p id="batch-settings">{settingsOf(b.spec)} · created {localTime(b.created_at)}</p>
        <progress id="batch-progress" max={Math.max(1, b.progress.total)} value={b.progress.done} />
        <span id="batch-count"> {b.progress.done} / {b.progress.total} · {b.status}</span>{" "}
        <button id="batch-cancel" disabled={!running} onClick={() => post(`/api/batches/${encodeURIComponent(id)}/cancel`).then(() => setReload((n) => n + 1)).catch((e) => setError(e.message))}>Cancel</button>
        <a id="batch-results-csv" href={`/api/batches/${id}/results.csv`}>results (CSV)</a>{" "}
        <a id="batch-trials-csv" href={`/api/batches/${id}/trials.csv`}>trials (CSV)</a>{" "}
        <ExportButton body={{ batch: id }} disabled={successes === 0} label="Export successes (LeRobot)" />
        {error && <span className="fail">{error}</span>}
      </section>
      <section><h3>Success per task (95 % Wilson interval)</h3>
        <SuccessChart results={b.results} />
        <table id="batch-table"><thead><tr><th>task</th><th>done</th><th>success</th><th>95 % CI</th></tr></thead>
          <tbody>{b.results.map((r) => (
            <tr key={r.task} data-task={r.task}><td>{r.task}</td><td>{r.done}/{r.total}</td><td className="rate">{pct(r.success_rate)}</td><td className="ci95">{interval(r.ci95)}</td></tr>))}</tbody></table>
      </section>
      <section className="timing"><h3>Where the time went</h3>
        <div className="charts">
          <div><h4>Per primitive (simulated s per trial)</h4>
            <TimingChart rows={timing} trialsPerTask={Object.fromEntries(b.results.map((r) => [r.task, r.done]))} /></div>
          <div><h4>Per pipeline phase (wall s per trial)</h4><PhaseChart rows={phases} /></div>
        </div>
      </section>
      <section><h3>Trials</h3><div id="batch-trials"><TrialTable items={b.trials} /></div></section>
    </div>
  );
}
