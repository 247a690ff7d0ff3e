// Export trials as a LeRobot dataset (POST /api/exports), then offer the zip.
import { useEffect, useRef, useState } from "react";
import { post } from "../api/client";

interface Result { episodes: number; frames: number; bytes: number; download: string; skipped: { reason: string }[] }

export function ExportButton({ body, disabled, label }: { body: Record<string, unknown>; disabled: boolean; label: string }) {
  const [failures, setFailures] = useState(false);
  const [state, setState] = useState<{ busy?: boolean; error?: string; result?: Result }>({});
  // a result (or error) belongs to the selection it was made from: a changed selection clears it, and an answer
  // for an earlier selection is dropped
  const key = JSON.stringify(body);
  const current = useRef(key);
  useEffect(() => { current.current = key; setState({}); }, [key]);
  const run = async () => {
    const asked = key;
    setState({ busy: true });
    try {
      const result = await post<Result>("/api/exports", { ...body, success_only: !failures });
      if (current.current === asked) setState({ result });
    } catch (e) { if (current.current === asked) setState({ error: (e as Error).message }); }
  };
  const r = state.result;
  return (
    <span className="export">
      <button id="export-selected" disabled={disabled || state.busy} onClick={run}>{label}</button>
      <label><input type="checkbox" id="export-failures" checked={failures} onChange={(e) => setFailures(e.target.checked)} /> include failures</label>
      <span id="export-result">
        {state.busy && "exporting…"}
        {state.error && <span className="fail">{state.error}</span>}
        {r && <>{r.episodes} episode(s), {r.frames} frames, {(r.bytes / 1e6).toFixed(1)} MB <a id="export-download" href={r.download}>download (zip)</a>
          {r.skipped.length > 0 && ` · ${r.skipped.length} skipped (${r.skipped[0].reason})`}</>}
      </span>
    </span>
  );
}
