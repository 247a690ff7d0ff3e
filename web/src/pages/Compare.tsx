// Two trials side by side: the plan diff (line by line), the first node where they diverge (a different node,
// or the same node with a different outcome), and both timelines on one time axis.
import { useEffect, useState } from "react";
import { api } from "../api/client";
import type { Trial } from "../api/types";
import { type Bar, Timeline } from "../components/Timeline";
import { VerdictBadge } from "../components/VerdictBadge";
import { endOf, leaves, withoutPauses } from "../lib/trialTime";

export function diffLines(a: string[], b: string[]): { op: " " | "-" | "+"; line: string }[] {
  // longest common subsequence: plans are a few dozen lines
  const n = a.length, m = b.length;
  const L = Array.from({ length: n + 1 }, () => new Array<number>(m + 1).fill(0));
  for (let i = n - 1; i >= 0; i--) for (let j = m - 1; j >= 0; j--) L[i][j] = a[i] === b[j] ? L[i + 1][j + 1] + 1 : Math.max(L[i + 1][j], L[i][j + 1]);
  const out: { op: " " | "-" | "+"; line: string }[] = [];
  let i = 0, j = 0;
  while (i < n || j < m) {
    if (i < n && j < m && a[i] === b[j]) { out.push({ op: " ", line: a[i] }); i++; j++; }
    else if (i < n && (j >= m || L[i + 1][j] >= L[i][j + 1])) out.push({ op: "-", line: a[i++] });
    else out.push({ op: "+", line: b[j++] });
  }
  return out;
}

export function firstDivergence(a: Trial, b: Trial): string {
  const la = leaves(a.nodes ?? {}), lb = leaves(b.nodes ?? {});
  for (let i = 0; i < Math.max(la.length, lb.length); i++) {
    const x = la[i], y = lb[i];
    if (!x || !y) return `${(x ?? y)!.path}: only ${x ? "A" : "B"} ran it`;
    if (x.path !== y.path || x.kind !== y.kind) return `${x.path}: A ran ${x.kind}, B ran ${y.kind}${x.path !== y.path ? ` (at ${y.path})` : ""}`;
    if (x.status !== y.status) return `${x.path} (${x.kind}): A ${x.status}, B ${y.status}`;
  }
  return "none: the same nodes ran with the same outcomes";
}

export function Compare({ a, b }: { a: string; b: string }) {
  const [trials, setTrials] = useState<[Trial, Trial] | null>(null);
  const [error, setError] = useState("");
  const [cursor, setCursor] = useState(0);
  useEffect(() => {
    Promise.all([a, b].map((id) => api<Trial>(`/api/trials/${encodeURIComponent(id)}`)))
      .then(([x, y]) => setTrials([x, y].map((t) => withoutPauses(t, t.events ?? []).trial) as [Trial, Trial]))
      .catch((e) => setError(e.message));
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
            <tr key={t.id}><td>{"AB"[k]}</td><td><a href={`#/trial/${t.id}`}>{t.id}</a></td><td>{t.task}</td><td>{t.planner}</td><td>{t.segmenter}</td><td>{t.seed}</td>
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
