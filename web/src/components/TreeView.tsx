// The behavior tree with each node's state at the cursor: collapsible composites, retries, post-condition
// results (the failure and reason a node recorded), breakpoints (click a leaf while the trial is live).
import { useState } from "react";
import type { NodeRecord, PlanNode } from "../api/types";
import type { NodeState } from "../lib/trialTime";

interface Props {
  root: PlanNode; states: Record<string, NodeState>; records: Record<string, NodeRecord>;
  breakpoints: Set<string>; onToggleBreakpoint?: (path: string) => void;
}

export function TreeView(props: Props) {
  return <ul className="tree" id="tree"><TreeNode {...props} node={props.root} path="tree" /></ul>;
}

function TreeNode(props: Props & { node: PlanNode; path: string }) {
  const { node, path, states, records, breakpoints, onToggleBreakpoint } = props;
  const [open, setOpen] = useState(true);
  const st = states[path] ?? { status: "pending", retries: 0, attempts: 0 };
  const rec = records[path];
  const leaf = !node.children;
  const params = Object.entries(node.params ?? {}).map(([k, v]) => `${k}=${typeof v === "object" ? JSON.stringify(v) : v}`).join(", ");
  const label = leaf ? `${node.primitive ?? node.type}(${params})` : `${node.type}${node.arm ? ` [${node.arm}]` : ""}`;
  const reason = st.reason || (st.status === rec?.status ? rec?.reason : "");
  const result = Object.entries(st.result ?? {}).map(([k, v]) => `${k}=${typeof v === "object" ? JSON.stringify(v) : v}`).join(", ");
  const cls = `node ${st.status}${breakpoints.has(path) ? " breakpoint" : ""}`;
  return (
    <li>
      {!leaf && <button className="twisty" aria-label={open ? "collapse" : "expand"} onClick={() => setOpen(!open)}>{open ? "▾" : "▸"}</button>}
      <span className={cls} data-path={path} data-status={st.status}
        title={`${path}${leaf && onToggleBreakpoint ? " (click: breakpoint)" : ""}${result ? `\n${result}` : ""}`}
        onClick={() => leaf && onToggleBreakpoint?.(path)}>{label}</span>
      {st.retries > 0 && <span className="retries">↻ {st.retries}</span>}
      {leaf && st.result && st.status === "succeeded" && <span className="result muted" data-path={path}>{result}</span>}
      {(st.status === "failed" || st.status === "aborted") && (reason || st.failure) &&
        <span className="reason">{st.failure ? `${st.failure}: ` : ""}{reason}</span>}
      {!leaf && open && (
        <ul>{node.children!.map((c, i) => <TreeNode key={i} {...props} node={c} path={`${path}.children[${i}]`} />)}</ul>
      )}
    </li>
  );
}
