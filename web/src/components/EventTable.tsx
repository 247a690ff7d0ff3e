// The trial's events as a filterable table (wall and simulated time); rows after the cursor are dimmed and the
// last one at or before it is marked.
import { useState } from "react";
import type { TrialEvent } from "../api/types";

const fmtDetail = (d: Record<string, unknown> | undefined) =>
  Object.entries(d ?? {}).map(([k, v]) => `${k}=${typeof v === "object" ? JSON.stringify(v) : String(v)}`).join("  ");

export function EventTable({ events, cursor, kinds, toSim, onSeek }:
  { events: TrialEvent[]; cursor: number; kinds: string[]; toSim: (t: number) => number; onSeek: (t: number) => void }) {
  const [kind, setKind] = useState("");
  const [text, setText] = useState("");
  const shown = events.filter((e) => (!kind || e.kind === kind) && (!text || `${e.node_path} ${fmtDetail(e.detail)}`.includes(text)));
  let at = -1;
  shown.forEach((e, i) => { if (e.t <= cursor) at = i; });
  return (
    <div className="events">
      <div className="filters">
        <select aria-label="event kind" name="event-kind" value={kind} onChange={(e) => setKind(e.target.value)}>
          <option value="">every kind</option>
          {kinds.map((k) => <option key={k}>{k}</option>)}
        </select>
        <input aria-label="filter events" name="event-filter" placeholder="node or detail contains…" value={text} onChange={(e) => setText(e.target.value)} />
        <span className="muted">{shown.length} / {events.length}</span>
      </div>
      <div className="scroll">
        <table id="event-table">
          <thead><tr><th>wall s</th><th>sim s</th><th>kind</th><th>node</th><th>detail</th></tr></thead>
          <tbody>
            {shown.map((e, i) => (
              <tr key={`${e.seq ?? i}-${e.t}`} className={`${e.t > cursor ? "future" : ""}${i === at ? " at-cursor" : ""}`} data-kind={e.kind} data-t={e.t} data-seq={e.seq} onClick={() => onSeek(e.t)}>
                <td>{e.t.toFixed(3)}</td><td>{(e.t_sim ?? toSim(e.t)).toFixed(2)}</td><td>{e.kind}</td><td>{e.node_path}</td><td>{fmtDetail(e.detail)}</td>
              </tr>
            ))}
          </tbody>
        </table>
      </div>
    </div>
  );
}
