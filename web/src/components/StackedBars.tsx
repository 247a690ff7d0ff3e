// A stacked bar per task (uPlot draws the axes, a draw hook the bars): each segment one key's value, one colour
// per key with a legend. Used for time per primitive and time per pipeline phase.
import { useEffect, useRef } from "react";
import uPlot from "uplot";
import "uplot/dist/uPlot.min.css";

export interface Segment { task: string; key: string; value: number }

const PALETTE = ["#4e79a7", "#f28e2b", "#59a14f", "#e15759", "#76b7b2", "#edc948", "#b07aa1", "#ff9da7", "#9c755f", "#bab0ac"];

export function StackedBars({ id, segments, yLabel }: { id: string; segments: Segment[]; yLabel: string }) {
  const el = useRef<HTMLDivElement>(null);
  const tasks = [...new Set(segments.map((r) => r.task))];
  const keys = [...new Set(segments.map((r) => r.key))];
  const color = (k: string) => PALETTE[keys.indexOf(k) % PALETTE.length];
  useEffect(() => {
    if (!el.current || !segments.length) return;
    const totals = tasks.map((t) => segments.filter((r) => r.task === t).reduce((s, r) => s + r.value, 0));
    const xs = tasks.map((_, i) => i);
    const opts: uPlot.Options = {
      width: Math.max(320, el.current.clientWidth || 600), height: 220, legend: { show: false }, cursor: { show: false },
      scales: { x: { time: false, auto: false, range: () => [-0.6, tasks.length - 0.4] }, y: { auto: false, range: () => [0, Math.max(...totals, 0.1) * 1.1] } },
      axes: [{ splits: () => xs, values: (_u, s) => s.map((i) => tasks[i] ?? ""), size: 40 }, { label: yLabel, size: 56 }],
      series: [{}, { show: false }],
      hooks: {
        draw: [(u) => {
          const ctx = u.ctx;
          ctx.save();
          const w = Math.min(60, (u.bbox.width / tasks.length) * 0.5);
          tasks.forEach((t, i) => {
            let base = 0;
            const x = u.valToPos(i, "x", true);
            for (const r of segments.filter((q) => q.task === t)) {
              const y0 = u.valToPos(base, "y", true), y1 = u.valToPos(base + r.value, "y", true);
              ctx.fillStyle = color(r.key);
              ctx.fillRect(x - w / 2, y1, w, y0 - y1);
              base += r.value;
            }
          });
          ctx.restore();
        }],
      },
    };
    const u = new uPlot(opts, [xs, xs.map(() => 0)], el.current);
    return () => u.destroy();
  }, [JSON.stringify(segments), yLabel]); // eslint-disable-line react-hooks/exhaustive-deps
  if (!segments.length) return <p className="muted" id={id}>no finished trial yet</p>;
  return (
    <div id={id}>
      <div ref={el} />
      <div className="legend">{keys.map((k) => <span key={k} data-key={k}><span className="swatch" style={{ background: color(k) }} /> {k}</span>)}</div>
    </div>
  );
}
