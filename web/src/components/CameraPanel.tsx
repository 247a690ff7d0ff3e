// What perception did up to the cursor. On top, the grounding(s) in effect at the cursor (the latest at or before
// it; a node resolving two labels makes two at one time): per camera, the detection image of that grounding (its
// kept mask and keypoint) and every prompt candidate with its detections and best score, the kept one marked.
// Below, the earlier groundings. A finished trial's cameras are also drawn at the cursor, from its recorded scene
// state. Trials stored before per-grounding images fall back to the one image per camera of the last frame.
import type { Artifact, Grounding } from "../api/types";
import { groundingOutcome } from "../lib/groundingOutcome";

const EPS = 1e-6;

export function CameraPanel({ trialId, groundings, artifacts, simCursor, replayable }:
  { trialId: string; groundings: Grounding[]; artifacts: Artifact[]; simCursor: number; replayable: boolean }) {
  const url = (name: string) => `/api/trials/${encodeURIComponent(trialId)}/artifacts/${encodeURIComponent(name)}`;
  const indexed = groundings.map((g, i) => ({ g, i, t: g.t_sim_s ?? 0 }));
  const done = indexed.filter((x) => x.t <= simCursor + EPS);
  const tNow = done.length ? Math.max(...done.map((x) => x.t)) : null;
  const current = tNow === null ? [] : done.filter((x) => Math.abs(x.t - tNow) <= EPS);
  const earlier = done.filter((x) => !current.includes(x)).reverse();
  const images = new Map<number, Artifact[]>();
  for (const a of artifacts) {
    if (a.kind === "grounding" && a.grounding !== undefined) images.set(a.grounding, [...(images.get(a.grounding) ?? []), a]);
  }
  const lastFrame = artifacts.filter((a) => a.kind === "detections");
  const cameras = lastFrame.map((a) => a.camera ?? "");

  return (
    <div className="camera" id="camera-panel" data-groundings={done.length}>
      <div id="grounding-now" data-t={tNow ?? ""} data-indices={current.map((x) => x.i).join(",")}>
        {current.length === 0 && (
          <p className="muted">{groundings.length ? "no grounding yet at this time" : "no grounding recorded (this segmenter uses no camera, or nothing was resolved yet)"}</p>
        )}
        {current.map(({ g, i }) => (
          <GroundingView key={i} g={g} i={i} images={images.get(i) ?? []} url={url} />
        ))}
        {current.length > 0 && images.size === 0 && lastFrame.length > 0 && (
          <LastFrameImages artifacts={lastFrame} groundings={groundings} simCursor={simCursor} url={url} />
        )}
      </div>
      {replayable && (
        <div id="camera-at-cursor">
          {(cameras.length ? cameras : [""]).map((cam) => {
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
      {earlier.length > 0 && (
        <div id="groundings">
          <h5>earlier groundings</h5>
          {earlier.map(({ g, i }) => (
            <details key={i}>
              <summary><b>{g.label}</b> at {(g.t_sim_s ?? 0).toFixed(2)} s sim{groundingOutcome(g)}</summary>
              <GroundingView g={g} i={i} images={images.get(i) ?? []} url={url} lazy />
            </details>
          ))}
        </div>
      )}
    </div>
  );
}

function GroundingView({ g, i, images, url, lazy }:
  { g: Grounding; i: number; images: Artifact[]; url: (name: string) => string; lazy?: boolean }) {
  return (
    <div className="grounding" data-grounding={i} data-label={g.label}>
      {!lazy && <div className="grounding-title"><b>{g.label}</b> grounded at {(g.t_sim_s ?? 0).toFixed(2)} s sim{groundingOutcome(g)}</div>}
      {Object.entries(g.cameras ?? {}).map(([cam, c]) => {
        const img = images.find((a) => a.camera === cam);
        return (
          <div key={cam} className="grounding-camera" data-camera={cam}>
            {img && (
              <figure>
                <img className="detection-image" src={url(img.name)} alt={`detections of ${g.label}, ${cam}`} data-grounding={i}
                  loading={lazy ? "lazy" : undefined} />
              </figure>
            )}
            <table className="candidates">
              <caption>{cam}: kept {c.chosen ?? "none"}</caption>
              <thead><tr><th>prompt</th><th>detections</th><th>best score</th><th>verdict</th></tr></thead>
              <tbody>{c.candidates.map((k) => (
                <tr key={k.prompt} className={k.verdict === "chosen" ? "chosen" : ""}>
                  <td>{k.prompt}</td><td>{k.n_detections}</td><td>{k.best_score?.toFixed(4) ?? ""}</td><td>{k.verdict}</td>
                </tr>))}
              </tbody>
            </table>
          </div>
        );
      })}
    </div>
  );
}

/** Trials stored before per-grounding images: one image per camera, of the last grounding's frame. */
function LastFrameImages({ artifacts, groundings, simCursor, url }:
  { artifacts: Artifact[]; groundings: Grounding[]; simCursor: number; url: (name: string) => string }) {
  const last = Math.max(0, ...groundings.map((g) => g.t_sim_s ?? 0));
  return (
    <div id="detections">
      {artifacts.map((a) => (
        <figure key={a.name} data-camera={a.camera ?? a.name}>
          {simCursor + EPS >= last
            ? <img src={url(a.name)} alt={`detections, ${a.camera ?? a.name}`} />
            : <div className="placeholder">this trial kept one detection image per camera, of its last grounding ({last.toFixed(2)} s)</div>}
          <figcaption>{a.camera ?? a.name}</figcaption>
        </figure>
      ))}
    </div>
  );
}
