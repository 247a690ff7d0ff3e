import type { Trial } from "../api/types";

/** One planner call as the trace keeps it (spark_core/trial.py `_plan`): the prompt-synthesis call, then the BT call. */
interface PlannerCall {
  kind: string; model?: string | null; prompt?: unknown; response?: unknown; error?: string | null;
  usage?: Record<string, number>; cost_usd?: number; latency_s?: number;
  image?: { camera: string | null; size_px: [number, number]; sha256: string } | null;
}

const text = (x: unknown): string => (typeof x === "string" ? x : JSON.stringify(x, null, 2));

/** The LLM planner's calls of this trial: what was asked and answered, tokens, cost, latency, and the annotated
 * image the BT call got (stored with the trial's artifacts). Offline planners make none: nothing is shown. */
export function PlannerCalls({ trial }: { trial: Trial }) {
  const planning = (trial.protocol?.planning ?? {}) as { calls?: PlannerCall[] };
  const calls = planning.calls ?? [];
  if (!calls.length) return null;
  const image = (trial.artifacts ?? []).find((a) => a.kind === "planner_input");
  return (
    <details id="planner-calls"><summary>Planner calls ({calls.length})</summary>
      {calls.map((c, i) => (
        <div key={i} className="planner-call" data-kind={c.kind}>
          <b>{c.kind.replace("_", " ")}</b> · {c.model ?? "?"} · {Object.entries(c.usage ?? {}).filter(([, v]) => v).map(([k, v]) => `${k.replace("_tokens", "")} ${v}`).join(", ") || "no tokens"}
          {" · "}${(c.cost_usd ?? 0).toFixed(4)} · {(c.latency_s ?? 0).toFixed(2)} s{c.error ? <span className="fail"> · {c.error}</span> : null}
          {c.kind === "behavior_tree" && c.image && image && (
            <div><img className="planner-image" src={`/api/trials/${encodeURIComponent(trial.id)}/artifacts/${encodeURIComponent(image.name)}`}
              alt={`image sent with the BT call (${c.image.camera ?? "camera"})`} title={`SHA-256 ${c.image.sha256}`} /></div>
          )}
          <details><summary>prompt</summary><pre>{text(c.prompt)}</pre></details>
          <details><summary>response</summary><pre>{text(c.response)}</pre></details>
        </div>
      ))}
    </details>
  );
}
