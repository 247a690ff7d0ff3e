// Comparing two trials: a line diff of their plans, and the first node where their runs part.
import type { Trial } from "../api/types";
import { leaves } from "./trialTime";

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
