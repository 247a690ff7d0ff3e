// Where each task's simulated time went, per primitive of its plans: a stacked bar per task (uPlot), each segment
// the mean simulated seconds a trial spent in that primitive.
import { useEffect, useRef } from "react";
import uPlot from "uplot";
import "uplot/dist/uPlot.min.css";

export interface TimingRow { task: string; primitive: string; runs: number; mean_sim_s: number; mean_wall_s: number }

const PALETTE = ["#4e79a7", "#f28e2b", "#59a14f", "#e15759", "#76b7b2", "#edc948", "#b07aa1", "#ff9da7", "#9c755f", "#bab0ac"];

export function TimingChart({ rows, trialsPerTask }: { rows: TimingRow[]; trialsPerTask: Record<string, number> }) {
  const el = useRef<HTMLDivElement>(null);
  const tasks = [...new Set(rows.map((r) => r.task))];
  const prims = [...new Set(rows.map((r) => r.primitive))];
  const color = (p: string) => PALETTE[prims.indexOf(p) % PALETTE.length];
  const perTrial = (r: TimingRow) => (r.mean_sim_s * r.runs) / Math.max(1, trialsPerTask[r.task] ?? 1);
  useEffect(() => {
    if (!el.current || !rows.length) return;
    const totals = tasks.map((t) => rows.filter((r) => r.task === t).reduce((s, r) => s + perTrial(r), 0));
    const xs = tasks.map((_, i) => i);
    const opts: uPlot.Options = {
      width: Math.max(320, el.current.clientWidth || 600), height: 220, legend: { show: false }, cursor: { show: false },
      scales: { x: { time: false, auto: false, range: () => [-0.6, tasks.length - 0.4] }, y: { auto: false, range: () => [0, Math.max(...totals, 0.1) * 1.1] } },
      axes: [{ splits: () => xs, values: (_u, s) => s.map((i) => tasks[i] ?? ""), size: 40 }, { label: "simulated s per trial", size: 56 }],
      series: [{}, { show: false }],
      hooks: {
        draw: [(u) => {
          const ctx = u.ctx;
          ctx.save();
          const w = Math.min(60, (u.bbox.width / tasks.length) * 0.5);
          tasks.forEach((t, i) => {
            let base = 0;
            const x = u.valToPos(i, "x", true);
            for (const r of rows.filter((q) => q.task === t)) {
              const y0 = u.valToPos(base, "y", true), y1 = u.valToPos(base + perTrial(r), "y", true);
              ctx.fillStyle = color(r.primitive);
              ctx.fillRect(x - w / 2, y1, w, y0 - y1);
              base += perTrial(r);
            }
          });
          ctx.restore();
        }],
      },
    };
    const u = new uPlot(opts, [xs, xs.map(() => 0)], el.current);
    return () => u.destroy();
  }, [JSON.stringify(rows), JSON.stringify(trialsPerTask)]); // eslint-disable-line react-hooks/exhaustive-deps
  if (!rows.length) return <p className="muted">no finished trial yet</p>;
  return (
    <div id="timing-chart">
      <div ref={el} />
      <div className="legend">{prims.map((p) => <span key={p}><span className="swatch" style={{ background: color(p) }} /> {p}</span>)}</div>
    </div>
  );
}
