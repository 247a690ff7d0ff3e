// The trial as a score: one row per leaf node, a bar per run coloured by outcome, on a time axis (uPlot). Click
// or drag on it to move the shared cursor.
import { useEffect, useRef } from "react";
import uPlot from "uplot";
import "uplot/dist/uPlot.min.css";

export interface Bar { row: string; start: number; end: number; status: string; title: string }

const COLORS: Record<string, string> = { succeeded: "#43a047", failed: "#e53935", running: "#f9a825", aborted: "#8e24aa", paused: "#1e88e5" };

export function Timeline({ bars, end, cursor, onSeek, id = "timeline", label = "wall time since start (s)" }:
  { bars: Bar[]; end: number; cursor: number; onSeek: (t: number) => void; id?: string; label?: string }) {
  const el = useRef<HTMLDivElement>(null);
  const plot = useRef<uPlot | null>(null);
  const cursorRef = useRef(cursor);
  const seekRef = useRef(onSeek);
  cursorRef.current = cursor;
  seekRef.current = onSeek;
  const rows = [...new Set(bars.map((b) => b.row))];

  useEffect(() => {
    if (!el.current) return;
    const width = Math.max(300, el.current.clientWidth || 600);
    const opts: uPlot.Options = {
      width, height: Math.max(130, 60 + 26 * rows.length),
      legend: { show: false }, cursor: { y: false, drag: { x: false, y: false } },
      scales: { x: { time: false, auto: false, range: () => [0, end] }, y: { auto: false, range: () => [-0.5, Math.max(0.5, rows.length - 0.5)] } },
      axes: [
        { label, labelSize: 18, size: 34 },
        { size: 160, splits: () => rows.map((_, i) => i), values: (_u, splits) => splits.map((i) => rows[i] ?? "") },
      ],
      series: [{}, { show: false }],
      hooks: {
        draw: [(u) => {
          const ctx = u.ctx;
          ctx.save();
          const h = Math.max(4, (u.bbox.height / Math.max(1, rows.length)) * 0.6);
          for (const b of bars) {
            const x0 = u.valToPos(b.start, "x", true), x1 = u.valToPos(Math.max(b.end, b.start), "x", true);
            const y = u.valToPos(rows.indexOf(b.row), "y", true);
            ctx.fillStyle = COLORS[b.status] ?? "#9e9e9e";
            ctx.fillRect(x0, y - h / 2, Math.max(2, x1 - x0), h);
          }
          const cx = u.valToPos(cursorRef.current, "x", true);
          ctx.strokeStyle = "#d32f2f"; ctx.lineWidth = 2;
          ctx.beginPath(); ctx.moveTo(cx, u.bbox.top); ctx.lineTo(cx, u.bbox.top + u.bbox.height); ctx.stroke();
          ctx.restore();
        }],
      },
    };
    const u = new uPlot(opts, [[0, end], [0, 0]], el.current);
    plot.current = u;
    let dragging = false;
    const seek = (e: MouseEvent) => seekRef.current(Math.min(end, Math.max(0, u.posToVal(e.offsetX, "x"))));
    const down = (e: MouseEvent) => { dragging = true; seek(e); };
    const move = (e: MouseEvent) => { if (dragging) seek(e); };
    const up = () => { dragging = false; };
    u.over.addEventListener("mousedown", down);
    u.over.addEventListener("mousemove", move);
    window.addEventListener("mouseup", up);
    return () => { window.removeEventListener("mouseup", up); u.destroy(); plot.current = null; };
  }, [JSON.stringify(bars), end, rows.length]); // eslint-disable-line react-hooks/exhaustive-deps

  useEffect(() => { plot.current?.redraw(false); }, [cursor]);
  return (
    <div className="timeline" id={id} data-bars={bars.length}>
      <div ref={el} />
      <div className="bar-titles" hidden>{bars.map((b, i) => <span key={i}>{b.title}</span>)}</div>
    </div>
  );
}
