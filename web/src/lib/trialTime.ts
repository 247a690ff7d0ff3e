// One trial's time model for the shared cursor. Events carry wall seconds since the trial started (`t`) and the
// world's simulated seconds when they happened (`t_sim`), the clock of the recorded scene states and groundings:
// the cursor's simulated time is read from the events around it. Records stored before events had `t_sim`
// fall back to `leafAnchors`, an estimate from the leaves' simulated durations.
import type { Catalog, NodeRecord, Trial, TrialEvent } from "../api/types";

export interface Anchor { wall: number; sim: number }

/** The nodes that ran and hold no others (primitive calls), by start time. */
export function leaves(nodes: Record<string, NodeRecord>): NodeRecord[] {
  const paths = Object.keys(nodes);
  const isLeaf = (p: string) => !paths.some((q) => q.startsWith(`${p}.children[`));
  return Object.values(nodes)
    .filter((n) => isLeaf(n.path) && n.started_t !== null)
    .sort((a, b) => (a.started_t ?? 0) - (b.started_t ?? 0));
}

/** (wall s, simulated s) pairs, increasing in both: each event's own pair; the trial's simulated end (after the
 * last event the world settles) at `end` wall s. Old records without `t_sim` get `leafAnchors`. */
export function anchors(trial: Trial, events: TrialEvent[], end: number): Anchor[] {
  const timed = events.filter((e) => e.t_sim !== undefined && e.t_sim !== null);
  if (!timed.length) return leafAnchors(trial);
  const out: Anchor[] = [];
  for (const e of timed) {
    const prev = out[out.length - 1];
    const a = { wall: e.t, sim: e.t_sim as number };
    if (!prev) out.push(a);
    else if (a.wall >= prev.wall && a.sim >= prev.sim) {
      if (a.wall === prev.wall) prev.sim = a.sim; // same instant: the later event's simulated time
      else out.push(a);
    }
  }
  const last = out[out.length - 1];
  const simEnd = trial.sim_time_s ?? last.sim;
  if (end > last.wall && simEnd >= last.sim) out.push({ wall: end, sim: simEnd });
  return out;
}

/** Estimated (wall s, simulated s) pairs from the leaves' simulated durations, for records whose events have no
 * `t_sim`: leaves run one after another (a parallel node's arms share the clock), so a leaf's simulated span is
 * placed after the simulated time of those before it; wall time maps to simulated time linearly inside a leaf. */
export function leafAnchors(trial: Trial): Anchor[] {
  const out: Anchor[] = [{ wall: 0, sim: 0 }];
  let sim = 0;
  let wallEnd = 0;
  for (const n of leaves(trial.nodes ?? {})) {
    const start = Math.max(n.started_t ?? 0, wallEnd);
    const end = Math.max(n.finished_t ?? start, start);
    if (start > out[out.length - 1].wall) out.push({ wall: start, sim });
    if (n.started_t !== null && n.started_t < wallEnd) continue; // overlaps the previous leaf: same clock
    sim += n.sim_time_s ?? 0;
    out.push({ wall: end, sim });
    wallEnd = end;
  }
  // the record's simulated total also counts time outside the leaves' own spans (perception between them):
  // spread it so the cursor's end is the trial's end
  const total = trial.sim_time_s ?? 0;
  if (sim > 0 && total > sim) for (const a of out) a.sim *= total / sim;
  return out;
}

export function wallToSim(a: Anchor[], wall: number): number {
  if (wall <= a[0].wall) return a[0].sim;
  for (let i = 1; i < a.length; i++) {
    if (wall <= a[i].wall) {
      const f = (wall - a[i - 1].wall) / Math.max(1e-9, a[i].wall - a[i - 1].wall);
      return a[i - 1].sim + f * (a[i].sim - a[i - 1].sim);
    }
  }
  return a[a.length - 1].sim;
}

/** Wall seconds the trial ran, not counting the time it spent paused (a pause lasts until the next event; a
 * pause still open when the events end lasts until `end`, the trial's recorded wall time, or the last event). */
export function activeWall(events: TrialEvent[], end: number | null): number {
  const last = end ?? (events.length ? events[events.length - 1].t : 0);
  const spans = pausedSpans(events);
  let paused = spans.reduce((sum, [a, b]) => sum + (b - a), 0);
  const tail = events.length ? events[events.length - 1] : null;
  if (tail?.kind === "paused") paused += Math.max(0, last - tail.t);
  return Math.max(0, last - paused);
}

export interface NodeState {
  status: string; retries: number; attempts: number; reason?: string; failure?: string | null;
  result?: Record<string, unknown>; // the detail of its last succeeded/failed event: what its post-condition measured
}

/** Each node's state once every event up to `t` (wall s) has happened; `final`: the trial's recorded end. */
export function treeStateAt(cat: Catalog, trial: Trial, events: TrialEvent[], t: number, final: boolean): Record<string, NodeState> {
  const out: Record<string, NodeState> = {};
  for (const e of events) {
    if (e.t > t) break;
    const s = (out[e.node_path] ??= { status: "pending", retries: 0, attempts: 0 });
    const status = cat.event_node_status[e.kind];
    if (status) s.status = status;
    if (e.kind === "started") s.attempts += 1;
    if (e.kind === "retrying") s.retries += 1;
    if (e.kind === "failed") s.reason = String(e.detail?.reason ?? e.detail?.error ?? "");
    if (e.kind === "succeeded" || e.kind === "failed") s.result = e.detail;
  }
  if (final) {
    // The record is the truth at the end: an abort leaves nodes "aborted" (no event says so), reasons are kept.
    for (const [path, n] of Object.entries(trial.nodes ?? {})) {
      out[path] = { ...out[path], status: n.status, retries: n.retries, attempts: n.attempts, reason: n.reason, failure: n.failure };
    }
    if (trial.verdict === "aborted" || trial.verdict === "interrupted" || trial.verdict === "crashed" || trial.verdict === "timeout") {
      for (const s of Object.values(out)) if (s.status === "running" || s.status === "paused") s.status = "aborted";
    }
  }
  return out;
}

/** The trial's last instant on the cursor (wall s). */
export function endOf(trial: Trial, events: TrialEvent[]): number {
  const lastEvent = events.length ? events[events.length - 1].t : 0;
  const lastNode = Math.max(0, ...Object.values(trial.nodes ?? {}).map((n) => n.finished_t ?? 0));
  return Math.max(lastEvent, lastNode, 0.001);
}

/** Paused spans [from, to] (wall s): from a "paused" event to the trial's next event. */
export function pausedSpans(events: TrialEvent[]): [number, number][] {
  const out: [number, number][] = [];
  events.forEach((e, i) => {
    if (e.kind !== "paused") return;
    const next = events.slice(i + 1).find((x) => x.t > e.t);
    if (next) out.push([e.t, next.t]);
  });
  return out;
}

/** Wall time with the paused spans cut out (what the timeline and the cursor use). */
export function unpaused(spans: [number, number][], t: number): number {
  let cut = 0;
  for (const [a, b] of spans) {
    if (t >= b) cut += b - a;
    else if (t > a) cut += t - a;
  }
  return t - cut;
}

/** The trial and its events on the unpaused clock. */
export function withoutPauses(trial: Trial, events: TrialEvent[]): { trial: Trial; events: TrialEvent[] } {
  const spans = pausedSpans(events);
  if (!spans.length) return { trial, events };
  const f = (t: number | null) => (t === null ? null : unpaused(spans, t));
  const nodes = Object.fromEntries(Object.entries(trial.nodes ?? {}).map(([p, n]) => [p, { ...n, started_t: f(n.started_t), finished_t: f(n.finished_t) }]));
  return { trial: { ...trial, nodes }, events: events.map((e) => ({ ...e, t: unpaused(spans, e.t) })) };
}
