// The trial workspace: tree, 3D view, camera panel, events and timeline on one screen, all on one time cursor.
// Live: the cursor follows the newest event; finished: scrub the timeline or play the replay at 0.25x-4x.
import { useEffect, useMemo, useRef, useState } from "react";
import { Panel, PanelGroup, PanelResizeHandle } from "react-resizable-panels";
import { api, post, wsUrl } from "../api/client";
import { isPrivileged, PRIVILEGED_NOTE, useCatalog } from "../api/catalog";
import type { Catalog, Trial, TrialEvent } from "../api/types";
import { CameraPanel } from "../components/CameraPanel";
import { PlannerCalls } from "../components/PlannerCalls";
import { EventTable } from "../components/EventTable";
import { Legend } from "../components/Legend";
import { type Bar, Timeline } from "../components/Timeline";
import { TreeView } from "../components/TreeView";
import { VerdictBadge } from "../components/VerdictBadge";
import { ViserView } from "../components/ViserView";
import { activeWall, anchors, endOf, leaves, treeStateAt, wallToSim, withoutPauses } from "../lib/trialTime";

const SPEEDS = [0.25, 0.5, 1, 2, 4];
const LIVE_POLL_MS = 1000;
const CLOCK_TICK_MS = 100;

export function TrialPage({ id }: { id: string }) {
  const cat = useCatalog();
  const [rawTrial, setTrial] = useState<Trial | null>(null);
  const [rawEvents, setEvents] = useState<TrialEvent[]>([]);
  const [closed, setClosed] = useState(false);
  const [error, setError] = useState("");
  const [loadError, setLoadError] = useState("");
  const [cursor, setCursor] = useState<number | null>(null); // null: follow the newest event / the end
  const [playing, setPlaying] = useState(false);
  const [speed, setSpeed] = useState(1);
  const [control, setControl] = useState<string>("");
  const [breakpoints, setBreakpoints] = useState<Set<string>>(new Set());

  // Bumped whenever an event or a control answer sets the control state: a record fetched before that is older
  // than it (a start_paused trial's "paused" event can overtake the fetch its first event started) and must not
  // overwrite it.
  const controlEpoch = useRef(0);
  // Every read of the record is numbered: an answer overtaken by a later read's (a live poll answered after the
  // end's refresh) is not shown over it.
  const reads = useRef({ sent: 0, shown: 0 });
  // The header's clock while the trial runs: the newest event's time plus the time since it was published, on
  // this browser's clock less the smallest delay seen between publication and arrival (any clock offset).
  const lag = useRef(Infinity);
  const [now, setNow] = useState(() => Date.now());
  const fetchTrial = () => {
    const n = ++reads.current.sent;
    return api<Trial>(`/api/trials/${encodeURIComponent(id)}`).then((t) => {
      const fresh = n > reads.current.shown;
      if (fresh) { reads.current.shown = n; setTrial(t); }
      return { t, fresh };
    });
  };
  const refresh = () => {
    const epoch = controlEpoch.current;
    return fetchTrial().then(({ t, fresh }) => {
    if (!fresh) return t;
    if (t.control_state && controlEpoch.current === epoch) setControl(t.control_state);
    if (t.breakpoints) setBreakpoints(new Set(t.breakpoints));
    return t;
    });
  };

  useEffect(() => {
    setTrial(null); setEvents([]); setClosed(false); setCursor(null); setPlaying(false); setLoadError("");
    lag.current = Infinity;
    refresh().catch((e) => setLoadError(e.message));
    const ws = new WebSocket(wsUrl(`/api/trials/${encodeURIComponent(id)}/events`));
    (window as unknown as { sparkSockets?: WebSocket[] }).sparkSockets?.push(ws); // tests count open sockets
    let gotPlan = false;
    ws.onmessage = (msg) => {
      const ev = JSON.parse(msg.data) as TrialEvent;
      if (ev.kind === "closed") {
        setClosed(true);
        refresh().catch(() => {});
        return;
      }
      // browser clock minus server clock (plus delivery): from the send time, since a replayed event's wall_s is old
      const sent = ev.sent_s ?? ev.wall_s;
      if (sent) lag.current = Math.min(lag.current, Date.now() / 1000 - sent);
      setEvents((es) => [...es, ev]);
      if (ev.kind === "paused") { controlEpoch.current++; setControl("paused"); }
      else if (ev.kind === "started") { controlEpoch.current++; setControl((c) => (c === "paused" ? "running" : c || "running")); }
      if (!gotPlan) { gotPlan = true; refresh().catch(() => {}); }
    };
    ws.onclose = () => { setTimeout(() => refresh().catch(() => {}), 200); };
    return () => ws.close(); // leaving the page (or opening another trial) ends this trial's stream
  }, [id]); // eslint-disable-line react-hooks/exhaustive-deps

  // one clock for the cursor, the timeline and the table: wall seconds with the paused spans cut out
  const evsRaw = rawEvents.length ? rawEvents : rawTrial?.events ?? [];
  const { trial, events } = useMemo(
    () => (rawTrial ? withoutPauses(rawTrial, evsRaw) : { trial: null, events: evsRaw }),
    [rawTrial, evsRaw],
  );
  const finished = trial?.status === "done" || trial?.status === "interrupted";
  const live = !!trial && !finished && !closed;

  // live: the record is re-read every second for what the worker stores as it happens (each grounding and its
  // detection images: the camera panel shows them while the trial runs, not only once it has ended)
  useEffect(() => {
    if (!live) return;
    const timer = window.setInterval(() => { fetchTrial().catch(() => {}); }, LIVE_POLL_MS);
    const tick = window.setInterval(() => setNow(Date.now()), CLOCK_TICK_MS); // stops when the trial ends
    return () => { window.clearInterval(timer); window.clearInterval(tick); };
  }, [live, id]); // eslint-disable-line react-hooks/exhaustive-deps
  const end = trial ? endOf(trial, events) : 1;
  const t = cursor ?? end;
  const anc = useMemo(() => (trial ? anchors(trial, events, end) : [{ wall: 0, sim: 0 }]), [trial, events, end]);
  const toSim = (w: number) => wallToSim(anc, w);

  // the replay: the cursor advances at `speed` x wall time
  const raf = useRef<number | null>(null);
  useEffect(() => {
    if (!playing) return;
    let last = performance.now();
    const tick = (now: number) => {
      const dt = ((now - last) / 1000) * speed;
      last = now;
      setCursor((c) => {
        const next = Math.min(end, (c ?? 0) + dt);
        if (next >= end) setPlaying(false);
        return next;
      });
      raf.current = requestAnimationFrame(tick);
    };
    raf.current = requestAnimationFrame(tick);
    return () => { if (raf.current !== null) cancelAnimationFrame(raf.current); };
  }, [playing, speed, end]);

  // keys, as in replay tools: ←/→ the previous/next event, space play/pause (not while typing in a field)
  const keyState = useRef({ live: true, t: 0, times: [] as number[], end: 1 });
  keyState.current = { live, t: cursor ?? end, times: events.map((e) => e.t), end };
  useEffect(() => {
    const onKey = (e: KeyboardEvent) => {
      const k = keyState.current;
      if (k.live || (e.target as HTMLElement)?.closest?.("input, textarea, select")) return;
      if (e.key === "ArrowRight" || e.key === "ArrowLeft") {
        const next = e.key === "ArrowRight" ? k.times.find((x) => x > k.t + 1e-9) : [...k.times].reverse().find((x) => x < k.t - 1e-9);
        if (next !== undefined) { setPlaying(false); setCursor(next); e.preventDefault(); }
      } else if (e.key === " ") {
        if (k.t >= k.end) setCursor(0);
        setPlaying((p) => !p);
        e.preventDefault();
      }
    };
    window.addEventListener("keydown", onKey);
    return () => window.removeEventListener("keydown", onKey);
  }, []);

  if (loadError) return <section className="fail" id="load-error">{loadError}</section>;
  if (!trial || !cat) return <section>loading…</section>;

  const atEnd = !live && t >= end - 1e-9;
  const states = treeStateAt(cat, trial, events, t, atEnd);
  const evs = events;
  const bars: Bar[] = leaves(trial.nodes ?? {}).map((n) => ({
    row: `${n.kind} ${n.path.replace("tree", "").replace(/children/g, "")}`, start: n.started_t ?? 0, end: n.finished_t ?? end,
    status: n.status, title: `${n.path} ${n.kind} ${(n.duration_s ?? 0).toFixed(3)} s`,
  }));
  const act = async (action: string, extra: Record<string, unknown> = {}) => {
    const epoch = controlEpoch.current;
    try {
      const r = await post<{ state: string }>(`/api/trials/${encodeURIComponent(id)}/control`, { action, ...extra });
      // an event that came while the answer was on its way is newer than it (a resume's "running" arriving after
      // the pause at the next breakpoint must not hide that pause)
      if (controlEpoch.current === epoch) { controlEpoch.current++; setControl(r.state); }
      setError("");
    } catch (e) { setError((e as Error).message); }
  };
  const toggleBreakpoint = live ? (path: string) => {
    const next = new Set(breakpoints);
    if (next.has(path)) next.delete(path); else next.add(path);
    setBreakpoints(next);
    act("breakpoints", { breakpoints: [...next] });
  } : undefined;
  const paused = live && control === "paused";
  const shownStatus = live ? (paused ? "paused" : trial.status === "queued" && !evs.length ? "queued" : "running") : trial.status;

  return (
    <div className="workspace">
      <Header trial={trial} cat={cat} status={shownStatus} activeS={activeWall(evsRaw, finished ? rawTrial!.wall_time_s : live ? liveNow(evsRaw, now, lag.current) : null)} />
      <div className="controls" id="controls">
        <button id="pause" disabled={!live || paused} onClick={() => act("pause")}>Pause</button>
        <button id="step" disabled={!paused} onClick={() => act("step")}>Step</button>
        <button id="resume" disabled={!paused} onClick={() => act("resume")}>Resume</button>
        <button id="abort" disabled={!live} onClick={() => act("abort")}>Abort</button>
        <span className="sep" />
        <button id="play" title="space" disabled={live} onClick={() => { if (t >= end) setCursor(0); setPlaying(!playing); }}>{playing ? "Pause replay" : "Play replay"}</button>
        <select id="speed" aria-label="replay speed" value={speed} onChange={(e) => setSpeed(Number(e.target.value))}>
          {SPEEDS.map((s) => <option key={s} value={s}>{s}x</option>)}
        </select>
        <input id="scrub" type="range" aria-label="time cursor" min={0} max={end} step="any" value={t} disabled={live}
          onChange={(e) => { setPlaying(false); setCursor(Number(e.target.value)); }} />
        <span id="cursor-time">{t.toFixed(2)} s wall (pauses cut) · {toSim(t).toFixed(2)} s sim</span>
        <a href={`/api/trials/${encodeURIComponent(id)}`} download={`${id}.json`}>trace (JSON)</a>
        {error && <span className="fail" id="control-error">{error}</span>}
      </div>
      <Legend cat={cat} />
      <PanelGroup direction="horizontal" className="panes" autoSaveId="spark-workspace-h">
        <Panel defaultSize={30} minSize={15}>
          <div className="pane" id="tree-pane"><h4>Behavior tree</h4>
            {trial.plan_tree
              ? <TreeView root={trial.plan_tree.tree} states={states} records={atEnd ? trial.nodes ?? {} : {}} breakpoints={breakpoints} onToggleBreakpoint={toggleBreakpoint} />
              : <NoPlan trial={trial} live={live} />}
          </div>
        </Panel>
        <PanelResizeHandle className="handle" />
        <Panel defaultSize={40} minSize={20}>
          <PanelGroup direction="vertical" autoSaveId="spark-workspace-mid">
            <Panel defaultSize={62} minSize={20}><div className="pane"><h4>3D view</h4><ViserView trialId={id} live={live} simTime={live ? null : toSim(t)} /></div></Panel>
            <PanelResizeHandle className="handle horizontal" />
            <Panel minSize={15}><div className="pane"><h4>Timeline</h4><Timeline label="wall time since start, pauses cut out (s)" bars={bars} end={end} cursor={t} onSeek={(x) => { setPlaying(false); setCursor(x); }} /></div></Panel>
          </PanelGroup>
        </Panel>
        <PanelResizeHandle className="handle" />
        <Panel defaultSize={30} minSize={15}>
          <PanelGroup direction="vertical" autoSaveId="spark-workspace-right">
            <Panel defaultSize={55} minSize={15}><div className="pane"><h4>Camera</h4>
              <CameraPanel trialId={id} groundings={trial.groundings ?? []} artifacts={trial.artifacts ?? []} simCursor={live ? Infinity : toSim(t)} replayable={!live && trial.status === "done" && !!trial.plan_tree} /></div></Panel>
            <PanelResizeHandle className="handle horizontal" />
            <Panel minSize={15}><div className="pane"><h4>Events</h4>
              <EventTable events={evs} cursor={t} kinds={cat.event_kind} toSim={toSim} onSeek={(x) => { if (!live) { setPlaying(false); setCursor(x); } }} /></div></Panel>
          </PanelGroup>
        </Panel>
      </PanelGroup>
    </div>
  );
}

/** A live trial's time now (its events' clock: s since it started): the newest event's time plus the time since
 * it was published; the newest event's own time when it carries no publication time. */
function liveNow(events: TrialEvent[], nowMs: number, lagS: number): number | null {
  const last = events.length ? events[events.length - 1] : null;
  if (!last) return null;
  if (!last.wall_s) return last.t;
  return last.t + Math.max(0, nowMs / 1000 - last.wall_s - (Number.isFinite(lagS) ? lagS : 0));
}

function Header({ trial, cat, status, activeS }: { trial: Trial; cat: Catalog; status: string; activeS: number }) {
  const task = cat.tasks.find((x) => x.name === trial.task);
  return (
    <section className="trial-header">
      <h3>Trial {trial.id}</h3>
      <div>
        {trial.task} · “{trial.instruction}” · planner {trial.planner} · segmenter {trial.segmenter}
        {isPrivileged(cat, trial) && <> <span className="privileged" id="privileged" title={PRIVILEGED_NOTE}>(privileged)</span></>} · seed {trial.seed}
        {trial.batch_id && <> · batch <a href={`#/batch/${trial.batch_id}`}>{trial.batch_id}</a></>}
      </div>
      <div>
        status <b id="status" data-status={status}>{status}</b> <VerdictBadge verdict={trial.verdict} id="verdict" />
        {" · "}wall <span id="wall-active">{activeS.toFixed(2)}</span> s (paused time not counted)
        {trial.sim_time_s !== null && <> · sim {trial.sim_time_s.toFixed(2)} s</>}
        {(trial.cost_usd ?? 0) > 0 && <> · ${trial.cost_usd!.toFixed(4)}</>}
      </div>
      <Explanation trial={trial} predicate={task?.predicate} />
      <PlannerCalls trial={trial} />
    </section>
  );
}

/** Why the trial ended as it did, in words. */
function Explanation({ trial, predicate }: { trial: Trial; predicate?: string }) {
  if (!trial.verdict || trial.verdict === "success") return null;
  let text = trial.reason || "";
  if (trial.verdict === "task_unmet") {
    const extra = trial.reason && !(predicate && trial.reason.includes(predicate)) ? ` ${trial.reason}` : "";
    text = `Every node of the tree passed, but the task's success condition was not met: ${predicate ?? "(unknown task)"}.${extra}`;
  } else if (trial.verdict === "planner_error") {
    text = `The planner produced no plan. What it said: ${trial.reason || "(nothing)"}`;
  } else if (trial.verdict === "aborted") {
    // the record's reason often says just that: not "Aborted by the operator: aborted by the operator"
    const own = trial.reason && !/^aborted by the operator\.?$/i.test(trial.reason.trim());
    text = `Aborted by the operator${own ? `: ${trial.reason}` : "."}`;
  } else if (trial.failed_node) {
    text = `${trial.failure ?? "failed"} at ${trial.failed_node}: ${trial.reason}`;
  }
  return <p className="explanation fail" id="explanation">{text}</p>;
}

function NoPlan({ trial, live }: { trial: Trial; live: boolean }) {
  if (live) return <p className="muted" id="no-plan">waiting for the plan…</p>;
  return <p className="fail" id="no-plan">No plan{trial.verdict ? ` (${trial.verdict})` : ""}: {trial.reason || "the trial ended before a plan was made"}</p>;
}
