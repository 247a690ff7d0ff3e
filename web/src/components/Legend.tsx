// What each node colour means (statuses from the catalog, plus the UI's own "breakpoint" outline).
import type { Catalog } from "../api/types";

export function Legend({ cat }: { cat: Catalog }) {
  const statuses = [...new Set([...cat.node_status, ...Object.values(cat.event_node_status)])];
  return (
    <div className="legend" id="legend">
      {statuses.map((s) => <span key={s} className={`node ${s}`}>{s}</span>)}
      <span className="node pending breakpoint">breakpoint</span>
      <span className="retries">↻ retries</span>
    </div>
  );
}
