// Where each task's time went: per primitive of its plans (mean simulated seconds a trial spent in each), and per
// phase of the trial pipeline (mean wall seconds a trial spent in setup, perception, planning, execution, ...).
import { StackedBars } from "./StackedBars";

export interface TimingRow { task: string; primitive: string; runs: number; mean_sim_s: number; mean_wall_s: number }
export interface PhaseRow { task: string; phase: string; trials: number; mean_wall_s: number }

export function TimingChart({ rows, trialsPerTask }: { rows: TimingRow[]; trialsPerTask: Record<string, number> }) {
  const segments = rows.map((r) => ({ task: r.task, key: r.primitive, value: (r.mean_sim_s * r.runs) / Math.max(1, trialsPerTask[r.task] ?? 1) }));
  return <StackedBars id="timing-chart" segments={segments} yLabel="simulated s per trial" />;
}

export function PhaseChart({ rows }: { rows: PhaseRow[] }) {
  const segments = rows.map((r) => ({ task: r.task, key: r.phase, value: r.mean_wall_s }));
  return <StackedBars id="phase-chart" segments={segments} yLabel="wall s per trial" />;
}
