// Paste or edit a plan in the paper's YAML format; it is validated as you type (POST /api/plans/validate) and
// each error is shown on the line of the exact path it names.
import { useEffect, useState } from "react";
import { type PlanValidation, post } from "../api/client";
import { linePaths } from "../lib/yamlPaths";
import { NodePalette } from "./NodePalette";

// `embodiment`: the robot set-up the plan is to run on; its arm tags are checked against that robot's arms too.
export function PlanEditor({ text, task, embodiment, onChange, onValid }:
  { text: string; task: string; embodiment?: string; onChange: (t: string) => void; onValid: (ok: boolean) => void }) {
  const [result, setResult] = useState<PlanValidation | null>(null);
  useEffect(() => {
    if (!text.trim()) { setResult(null); onValid(true); return; }
    const timer = setTimeout(() => {
      post<PlanValidation>("/api/plans/validate", embodiment ? { text, embodiment } : { text })
        .then((r) => { setResult(r); onValid(r.ok); })
        .catch((e) => { setResult({ ok: false, errors: [{ path: "", message: (e as Error).message }] }); onValid(false); });
    }, 250);
    return () => clearTimeout(timer);
  }, [text, embodiment]); // eslint-disable-line react-hooks/exhaustive-deps
  const paths = linePaths(text);
  const errors = result?.errors ?? [];
  const lineOf = (path: string) => {
    // the deepest line whose path is the error's path or contains it
    let best = -1;
    paths.forEach((p, i) => { if (p && (path === p || path.startsWith(p + ".") || path.startsWith(p + "["))) { if (best < 0 || p.length >= paths[best].length) best = i; } });
    return best;
  };
  const marked = new Map(errors.map((e) => [lineOf(e.path ?? ""), e]));
  return (
    <div className="plan-editor">
      <NodePalette text={text} task={task} onChange={onChange} />
      <textarea name="plan" spellCheck={false} rows={12} value={text} onChange={(e) => onChange(e.target.value)}
        placeholder="optional: a plan to run as given (the planner is not called), e.g. task: …&#10;tree:&#10;  type: sequence …" />
      {text.trim() && (
        <div className="plan-check" id="plan-check">
          {result?.ok && <div className="ok" id="plan-ok">plan is valid</div>}
          {errors.length > 0 && (
            <>
              <ol className="plan-lines">
                {text.split("\n").map((line, i) => (
                  <li key={i} className={marked.has(i) ? "error-line" : ""} data-path={paths[i]}>
                    <code>{line || " "}</code>{marked.has(i) && <span className="fail"> ← {marked.get(i)!.message}</span>}
                  </li>
                ))}
              </ol>
              <ul id="plan-errors">{errors.map((e, i) => <li key={i} className="fail"><code>{e.path || "(plan)"}</code>: {e.message}</li>)}</ul>
            </>
          )}
        </div>
      )}
    </div>
  );
}
