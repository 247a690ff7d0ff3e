// Trial summaries as a table; column headers sort (server-side) when `sort` is given.
import { isPrivileged, PRIVILEGED_NOTE, useCatalog } from "../api/catalog";
import type { TrialSummary } from "../api/types";
import { localTime } from "../lib/localTime";
import { VerdictBadge } from "./VerdictBadge";

export interface Column { key: string; label: string; sortKey?: string; cell: (t: TrialSummary) => React.ReactNode }

const num = (x: number | null | undefined, d = 2) => (x === null || x === undefined ? "" : x.toFixed(d));

export const COLUMNS: Column[] = [
  { key: "date", label: "date", sortKey: "created_at", cell: (t) => localTime(t.created_at) },
  { key: "id", label: "trial", cell: (t) => <a href={`#/trial/${t.id}`}>{t.id}</a> },
  { key: "task", label: "task", sortKey: "task", cell: (t) => t.task },
  { key: "planner", label: "planner", sortKey: "planner", cell: (t) => t.planner },
  { key: "segmenter", label: "segmenter", sortKey: "segmenter", cell: (t) => <Segmenter t={t} /> },
  { key: "seed", label: "seed", sortKey: "seed", cell: (t) => t.seed },
  { key: "batch", label: "batch", sortKey: "batch_id", cell: (t) => (t.batch_id ? <a href={`#/batch/${t.batch_id}`}>{t.batch_id}</a> : "") },
  { key: "status", label: "status", sortKey: "status", cell: (t) => t.status },
  { key: "verdict", label: "verdict", sortKey: "verdict", cell: (t) => <VerdictBadge verdict={t.verdict} /> },
  { key: "failure", label: "failing module", sortKey: "failure", cell: (t) => t.failure ?? "" },
  { key: "sim", label: "sim s", sortKey: "sim_time_s", cell: (t) => num(t.sim_time_s) },
  { key: "wall", label: "wall s", sortKey: "wall_time_s", cell: (t) => num(t.wall_time_s) },
  { key: "cost", label: "cost $", sortKey: "cost_usd", cell: (t) => num(t.cost_usd ?? 0, 4) },
  { key: "training", label: "training data", cell: (t) => (t.training_frames
    ? <span className="training" data-training={t.training_frames} title="recorded with capture: a LeRobot export takes it">{t.training_frames} frames</span>
    : "") },
];

/** The segmenter's name, marked when the trial's perception was privileged (as the catalog or the record says). */
export function Segmenter({ t }: { t: TrialSummary }) {
  const cat = useCatalog();
  return <>{t.segmenter}{isPrivileged(cat, t) && <> <span className="privileged" data-privileged="true" title={PRIVILEGED_NOTE}>privileged</span></>}</>;
}

export function TrialTable({ items, columns = COLUMNS, sort, onSort, picked, onPick }: {
  items: TrialSummary[]; columns?: Column[]; sort?: string; onSort?: (s: string) => void;
  picked?: Set<string>; onPick?: (id: string, on: boolean) => void;
}) {
  const key = sort?.replace(/^-/, "");
  return (
    <table className="trials">
      <thead><tr>
        {onPick && <th />}
        {columns.map((c) => (
          <th key={c.key} data-sort={c.sortKey} className={c.sortKey && onSort ? "sortable" : ""}
            onClick={() => c.sortKey && onSort?.(key === c.sortKey && !sort?.startsWith("-") ? `-${c.sortKey}` : c.sortKey)}>
            {c.label}{c.sortKey && key === c.sortKey ? (sort?.startsWith("-") ? " ▼" : " ▲") : ""}
          </th>))}
      </tr></thead>
      <tbody>
        {items.map((t) => (
          <tr key={t.id} data-id={t.id}>
            {onPick && <td><input type="checkbox" className="pick" value={t.id} checked={picked?.has(t.id) ?? false} onChange={(e) => onPick(t.id, e.target.checked)} /></td>}
            {columns.map((c) => <td key={c.key} data-col={c.key}>{c.cell(t)}</td>)}
          </tr>))}
      </tbody>
    </table>
  );
}
