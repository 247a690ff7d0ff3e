// Success rate per task with its 95 % Wilson interval (uPlot: a bar per task, the interval as a whisker).
import { useEffect, useRef } from "react";
import uPlot from "uplot";
import "uplot/dist/uPlot.min.css";
import type { BatchResult } from "../api/types";

export function SuccessChart({ results }: { results: BatchResult[] }) {
  const el = useRef<HTMLDivElement>(null);
  useEffect(() => {
    if (!el.current || !results.length) return;
    const xs = results.map((_, i) => i);
    const opts: uPlot.Options = {
      width: Math.max(320, el.current.clientWidth || 600), height: 220,
      legend: { show: false }, cursor: { show: false },
      scales: { x: { time: false, auto: false, range: () => [-0.6, results.length - 0.4] }, y: { auto: false, range: () => [0, 1] } },
      axes: [
        { splits: () => xs, values: (_u, s) => s.map((i) => results[i]?.task ?? ""), size: 40 },
        { splits: () => [0, 0.25, 0.5, 0.75, 1], values: (_u, s) => s.map((v) => `${Math.round(v * 100)} %`), label: "success", size: 56 },
      ],
      series: [{}, { show: false }],
      hooks: {
        draw: [(u) => {
          const ctx = u.ctx;
          ctx.save();
          const w = Math.min(60, (u.bbox.width / results.length) * 0.5);
          results.forEach((r, i) => {
            const x = u.valToPos(i, "x", true), y0 = u.valToPos(0, "y", true);
            if (r.success_rate !== null) {
              const y = u.valToPos(r.success_rate, "y", true);
              ctx.fillStyle = "#6fa8ff";
              ctx.fillRect(x - w / 2, y, w, y0 - y);
            }
            if (r.ci95 === null) return; // no judged trial: no bar and no whisker
            const lo = u.valToPos(r.ci95[0], "y", true), hi = u.valToPos(r.ci95[1], "y", true);
            ctx.strokeStyle = "#1d2330"; ctx.lineWidth = 2;
            ctx.beginPath(); ctx.moveTo(x, lo); ctx.lineTo(x, hi);
            ctx.moveTo(x - 6, lo); ctx.lineTo(x + 6, lo); ctx.moveTo(x - 6, hi); ctx.lineTo(x + 6, hi); ctx.stroke();
          });
          ctx.restore();
        }],
      },
    };
    const u = new uPlot(opts, [xs, xs.map(() => 0)], el.current);
    return () => u.destroy();
  }, [JSON.stringify(results)]); // eslint-disable-line react-hooks/exhaustive-deps
  return <div id="success-chart" ref={el} />;
}
