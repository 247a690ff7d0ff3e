// The 3D view (viser, relayed from the console's origin), bound to one trial: live, its own feed; finished,
// its recorded scene at the cursor's simulated time.
import { useEffect, useRef, useState } from "react";
import { api, post } from "../api/client";

export function ViserView({ trialId, live, simTime }: { trialId: string; live: boolean; simTime: number | null }) {
  const [info, setInfo] = useState<{ enabled: boolean; path?: string } | null>(null);
  const [error, setError] = useState("");
  const timer = useRef<number | null>(null);
  const latest = useRef<{ trialId: string; live: boolean; simTime: number | null }>({ trialId, live, simTime });
  latest.current = { trialId, live, simTime };
  useEffect(() => { api<{ enabled: boolean; path?: string }>("/api/viser").then(setInfo).catch(() => setInfo({ enabled: false })); }, []);
  useEffect(() => {
    if (!info?.enabled || timer.current !== null) return;
    // throttled, not debounced: while the replay plays the view keeps up (at most 20 requests a second)
    timer.current = window.setTimeout(() => {
      timer.current = null;
      const { trialId: id, live: isLive, simTime: t } = latest.current;
      const q = new URLSearchParams({ trial: id });
      if (!isLive && t !== null) q.set("t_sim_s", String(Math.max(0, t)));
      post<{ showing: string }>(`/api/viser/focus?${q}`).then(() => setError("")).catch((e) => setError(e.message));
    }, live ? 0 : 50);
  }, [info?.enabled, trialId, live, simTime === null ? null : Math.round(simTime * 25)]); // eslint-disable-line react-hooks/exhaustive-deps
  useEffect(() => () => { // leaving the page unbinds the view
    if (timer.current !== null) clearTimeout(timer.current);
    post("/api/viser/focus").catch(() => {});
  }, []);
  if (!info) return <div className="muted">…</div>;
  if (!info.enabled) return <div className="muted">3D view disabled (SPARK_VISER=0)</div>;
  return (
    <div className="viser">
      {error && <div className="muted" id="viser-note">{error}</div>}
      <iframe id="viser-frame" title="3D view" src={info.path} />
    </div>
  );
}
