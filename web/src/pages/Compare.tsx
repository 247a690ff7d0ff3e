// Two trials side by side: the plan diff (line by line), the first node where they diverge (a different node,
// or the same node with a different outcome), and both timelines on one time axis.
import { useEffect, useState } from "react";
import { api } from "../api/client";
import type { Trial } from "../api/types";
import { type Bar, Timeline } from "../components/Timeline";
import { Segmenter } from "../components/TrialTable";
import { VerdictBadge } from "../components/VerdictBadge";
import { diffLines, firstDivergence } from "../lib/compare";
import { endOf, leaves, withoutPauses } from "../lib/trialTime";

export function Compare({ a, b }: { a: string; b: string }) {
  const [trials, setTrials] = useState<[Trial, Trial] | null>(null);
  const [error, setError] = useState("");
  const [cursor, setCursor] = useState(0);
  useEffect(() => {
    let current = true; // an answer for a pair this page no longer shows is dropped
    setTrials(null); setError("");
    Promise.all([a, b].map((id) => api<Trial>(`/api/trials/${encodeURIComponent(id)}`)))
      .then(([x, y]) => { if (current) setTrials([x, y].map((t) => withoutPauses(t, t.events ?? []).trial) as [Trial, Trial]); })
      .catch((e) => { if (current) setError(e.message); });
    return () => { current = false; };
  }, [a, b]);
  if (error) return <section className="fail">{error}</section>;
  if (!trials) return <section>loading…</section>;
  const [x, y] = trials;
  const bars: Bar[] = [x, y].flatMap((t, k) => leaves(t.nodes ?? {}).map((n) => ({
    row: `${"AB"[k]} ${n.kind} ${n.path.replace("tree", "").replace(/children/g, "")}`, start: n.started_t ?? 0, end: n.finished_t ?? 0, status: n.status, title: n.path,
  })));
  const end = Math.max(endOf(x, []), endOf(y, []));
  return (
    <div className="compare">
      <section><h3>Compare</h3>
        <table><thead><tr><th /><th>trial</th><th>task</th><th>planner</th><th>segmenter</th><th>seed</th><th>verdict</th><th>wall s</th></tr></thead>
          <tbody>{[x, y].map((t, k) => (
            <tr key={t.id}><td>{"AB"[k]}</td><td><a href={`#/trial/${t.id}`}>{t.id}</a></td><td>{t.task}</td><td>{t.planner}</td><td data-segmenter={t.segmenter}><Segmenter t={t} /></td><td>{t.seed}</td>
              <td><VerdictBadge verdict={t.verdict} /></td><td>{t.wall_time_s?.toFixed(2)}</td></tr>))}</tbody></table>
        <p id="divergence"><b>First divergence:</b> {firstDivergence(x, y)}</p>
      </section>
      <section><h3>Timelines (one axis)</h3><Timeline id="compare-timeline" label="wall time since start, pauses cut out (s)" bars={bars} end={end} cursor={cursor} onSeek={setCursor} /></section>
      <section><h3>Plan diff (A → B)</h3>
        <pre id="plan-diff">{diffLines((x.plan_text ?? "").split("\n"), (y.plan_text ?? "").split("\n")).map((d, i) => (
          <div key={i} className={d.op === "+" ? "added" : d.op === "-" ? "removed" : ""}>{d.op} {d.line}</div>))}</pre>
      </section>
    </div>
  );
}
