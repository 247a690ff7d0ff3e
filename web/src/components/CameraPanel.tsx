// What perception did up to the cursor: each grounding (simulated time, label), per camera every prompt candidate
// with its detections and best score (the kept one marked), and the annotated detection image (masks, boxes,
// keypoints). The engine keeps one image per camera, of its last grounding: it is shown from that time on. A
// finished trial's cameras are also drawn at the cursor, from its recorded scene state.
import type { Grounding } from "../api/types";

export function CameraPanel({ trialId, groundings, images, simCursor, replayable }:
  { trialId: string; groundings: Grounding[]; images: { name: string; camera?: string }[]; simCursor: number; replayable: boolean }) {
  const done = groundings.filter((g) => (g.t_sim_s ?? 0) <= simCursor + 1e-6);
  const lastAt: Record<string, number> = {};
  for (const g of groundings) for (const cam of Object.keys(g.cameras ?? {})) lastAt[cam] = Math.max(lastAt[cam] ?? 0, g.t_sim_s ?? 0);
  return (
    <div className="camera" id="camera-panel" data-groundings={done.length}>
      {replayable && (
        <div id="camera-at-cursor">
          {(images.length ? images.map((a) => a.camera ?? "") : [""]).map((cam) => {
            const q = new URLSearchParams({ t_sim_s: (Math.floor(simCursor * 10) / 10).toFixed(1) });
            if (cam) q.set("camera", cam);
            return (
              <figure key={cam || "first"} data-camera={cam}>
                <img src={`/api/trials/${encodeURIComponent(trialId)}/camera.png?${q}`} alt={`${cam || "camera"} at the cursor`}
                  onError={(e) => { e.currentTarget.style.display = "none"; }} />
                <figcaption>{cam || "camera"} at {q.get("t_sim_s")} s sim (keypoints grounded so far)</figcaption>
              </figure>
            );
          })}
        </div>
      )}
      <div id="detections">
        {images.map((a) => {
          const cam = a.camera ?? a.name;
          const ready = simCursor + 1e-6 >= (lastAt[cam] ?? 0);
          return (
            <figure key={a.name} data-camera={cam}>
              {ready
                ? <img src={`/api/trials/${encodeURIComponent(trialId)}/artifacts/${encodeURIComponent(a.name)}`} alt={`detections, ${cam}`} />
                : <div className="placeholder">no detection image yet (recorded at {(lastAt[cam] ?? 0).toFixed(2)} s)</div>}
              <figcaption>{cam}{ready && lastAt[cam] !== undefined ? ` · at ${lastAt[cam].toFixed(2)} s sim` : ""}</figcaption>
            </figure>
          );
        })}
      </div>
      <div id="groundings">
        {done.length === 0 && <p className="muted">no grounding yet at this time</p>}
        {done.map((g, i) => (
          <details key={i} open={i === done.length - 1}>
            <summary><b>{g.label}</b> at {(g.t_sim_s ?? 0).toFixed(2)} s sim{g.keypoint ? "" : " · no keypoint"}</summary>
            {Object.entries(g.cameras ?? {}).map(([cam, c]) => (
              <table key={cam} className="candidates">
                <caption>{cam}: kept {c.chosen ?? "none"}</caption>
                <thead><tr><th>prompt</th><th>detections</th><th>best score</th><th>verdict</th></tr></thead>
                <tbody>{c.candidates.map((k) => (
                  <tr key={k.prompt} className={k.verdict === "chosen" ? "chosen" : ""}>
                    <td>{k.prompt}</td><td>{k.n_detections}</td><td>{k.best_score?.toFixed(4) ?? ""}</td><td>{k.verdict}</td>
                  </tr>))}
                </tbody>
              </table>
            ))}
          </details>
        ))}
      </div>
    </div>
  );
}
