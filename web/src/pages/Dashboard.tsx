// Start trials and batches: tasks grouped by suite with search, the chosen task's card, planner fields (model,
// one of the operator's endpoints), and an optional plan of your own, validated as you type.
import { useEffect, useRef, useState } from "react";
import { api, post, wsUrl } from "../api/client";
import type { BatchCreate, TrialCreate } from "../api/client";
import { useCatalog } from "../api/catalog";
import type { Catalog, Page, Task, TrialSummary } from "../api/types";
import { PlanEditor } from "../components/PlanEditor";
import { TrialTable } from "../components/TrialTable";
import { go } from "../lib/route";

const PACING: [string, string][] = [["", "as fast as possible"], ["1", "real time"], ["0.5", "0.5x"], ["0.25", "0.25x"]];

export function Dashboard() {
  const cat = useCatalog();
  const [task, setTask] = useState("");
  if (!cat) return <section>loading…</section>;
  const chosen = cat.tasks.find((t) => t.name === task) ?? cat.tasks[0];
  return (
    <div className="dashboard">
      <section className="task-browser"><h3>Tasks</h3><TaskBrowser cat={cat} value={chosen.name} onChange={setTask} /></section>
      <div className="dash-main">
        <TaskCard task={chosen} cat={cat} />
        <TrialForm cat={cat} task={chosen} />
        <BatchForm cat={cat} />
        <RecentTrials />
      </div>
    </div>
  );
}

function TaskBrowser({ cat, value, onChange }: { cat: Catalog; value: string; onChange: (t: string) => void }) {
  const [q, setQ] = useState("");
  const match = (t: Task) => !q || `${t.name} ${t.instruction}`.toLowerCase().includes(q.toLowerCase());
  return (
    <div id="task-browser">
      <input type="search" name="task-search" placeholder="search tasks…" value={q} onChange={(e) => setQ(e.target.value)} />
      {Object.keys(cat.suites).map((suite) => {
        const tasks = cat.tasks.filter((t) => t.suite === suite && match(t));
        if (!tasks.length) return null;
        return (
          <details key={suite} open={suite === "builtin" || !!q} data-suite={suite}>
            <summary>{suite} <span className="muted">({tasks.length})</span></summary>
            <ul>{tasks.map((t) => (
              <li key={t.name}><button className={`task-item${t.name === value ? " chosen" : ""}`} data-task={t.name} title={t.name} onClick={() => onChange(t.name)}>
                {t.name.includes(":") ? <><span className="muted">{t.name.split(":")[0]}</span> {t.name.split(":")[1].replace(/_/g, " ")}</> : t.name}</button></li>))}</ul>
          </details>
        );
      })}
    </div>
  );
}

function TaskCard({ task }: { task: Task; cat: Catalog }) {
  return (
    <section className="task-card" id="task-card" data-task={task.name}>
      <h3>{task.name} <span className="muted">({task.suite})</span></h3>
      <img className="preview" key={task.name} src={`/api/tasks/${encodeURIComponent(task.name)}/preview.png`} alt={`the ${task.name} scene at its start`} />
      <p>“{task.instruction}”</p>
      <dl>
        <dt>objects</dt><dd>{task.objects.join(", ") || "—"}</dd>
        <dt>success condition</dt><dd id="task-predicate">{task.predicate}</dd>
        <dt>embodiments</dt><dd>{task.embodiments.join(", ")}</dd>
        <dt>time limit</dt><dd>{task.max_sim_s} s simulated</dd>
        <dt>reference plan</dt><dd>{task.has_reference_plan ? "yes" : "no"}</dd>
      </dl>
    </section>
  );
}

function PlannerFields({ cat, planner, setPlanner }: { cat: Catalog; planner: string; setPlanner: (p: string) => void }) {
  const p = cat.planners.find((x) => x.name === planner);
  const endpoints = cat.endpoints.filter((e) => e.planner === planner);
  return (
    <>
      <label>Planner <select name="planner" value={planner} onChange={(e) => setPlanner(e.target.value)}>
        {cat.planners.map((x) => <option key={x.name} value={x.name} title={x.description}>{x.name}</option>)}</select></label>
      {p && !p.offline && <>
        <label>Model <input name="model" placeholder={p.default_model ?? "required"} required={p.needs_model} /></label>
        <label title="LLM endpoints the operator configured (spark.yaml endpoints:)">Endpoint <select name="endpoint">
          <option value="">vendor default</option>
          {endpoints.map((e) => <option key={e.name} value={e.name}>{e.name}</option>)}</select></label>
      </>}
    </>
  );
}

/** Why the instruction field is off: the chosen planner reads no instruction (the catalog's flag); the planners
 * that do, by name. */
const instructionNote = (cat: Catalog, planner: string) => {
  const readers = cat.planners.filter((p) => p.reads_instruction).map((p) => p.name);
  return `the ${planner} planner runs this task's hand-written plan and reads no instruction: choose ${readers.join(" or ")} to give your own`;
};

const segLabel = (s: { name: string; privileged: boolean }) => `${s.name}${s.privileged ? " (privileged)" : ""}`;

function TrialForm({ cat, task }: { cat: Catalog; task: Task }) {
  const [planner, setPlanner] = useState(cat.planners[0]?.name ?? "");
  const [plan, setPlan] = useState("");
  const [planOk, setPlanOk] = useState(true);
  const [error, setError] = useState("");
  const [busy, setBusy] = useState(false);
  // the robot chosen for this task ("": its default); a plan of your own is checked against the robot's arms
  const [embodiment, setEmbodiment] = useState("");
  const robot = task.embodiments.includes(embodiment) ? embodiment : "";
  const runsOn = robot || task.embodiments[0];
  const checkedOn = cat.embodiments.some((x) => x.name === runsOn) ? runsOn : undefined;
  const readsInstruction = (cat.planners.find((p) => p.name === planner)?.reads_instruction ?? true) || !!plan.trim();
  const note = instructionNote(cat, planner);
  // An instruction typed for a task stays with that task: choosing another task empties the field (blank: the
  // chosen task's own instruction, shown as the placeholder), never sending the old text with the new task; the
  // text left behind is offered for the new task (one click) and comes back when its task is chosen again.
  const [drafts, setDrafts] = useState<Record<string, string>>({});
  const [leftBehind, setLeftBehind] = useState<string | null>(null); // the task whose text the last switch left
  const shownTask = useRef(task.name);
  useEffect(() => {
    if (shownTask.current === task.name) return;
    const old = shownTask.current;
    shownTask.current = task.name;
    setLeftBehind(drafts[old]?.trim() ? old : null);
  }, [task.name]); // eslint-disable-line react-hooks/exhaustive-deps
  const instruction = drafts[task.name] ?? "";
  const setInstruction = (text: string) => setDrafts((d) => ({ ...d, [task.name]: text }));
  const offer = leftBehind && leftBehind !== task.name && !instruction.trim() ? drafts[leftBehind] ?? "" : "";
  const submit = async (e: React.FormEvent<HTMLFormElement>) => {
    e.preventDefault();
    const f = new FormData(e.currentTarget);
    const s = (k: string) => (f.get(k) as string | null) || null;
    const body: TrialCreate = {
      task: task.name, planner, segmenter: s("segmenter") ?? cat.default_segmenter, seed: Number(f.get("seed") ?? 0),
      start_paused: f.get("start_paused") === "on", capture: f.get("capture") === "on", breakpoints: [],
      recovery: true, adaptive: true,
    } as TrialCreate;
    if (s("instruction")) body.instruction = s("instruction");
    if (s("embodiment")) body.embodiment = s("embodiment");
    if (s("model")) body.model = s("model");
    if (s("endpoint")) body.endpoint = s("endpoint");
    if (s("pacing")) body.pacing = Number(s("pacing"));
    if (s("protocol")) body.protocol = s("protocol");
    if (plan.trim()) body.plan = plan;
    setBusy(true);
    try { go(`#/trial/${(await post<{ id: string }>("/api/trials", body)).id}`); }
    catch (err) { setError((err as Error).message); }
    finally { setBusy(false); }
  };
  return (
    <section><h3>New trial</h3>
      <form id="new-trial" onSubmit={submit}>
        <input type="hidden" name="task" value={task.name} />
        {/* the reference planner runs the task's hand-written plan and reads no instruction (the server refuses one
            it would ignore): the field is off, and says so, unless a planner that reads it or a plan is chosen */}
        <label>Instruction <input name="instruction" placeholder={task.instruction} className="wide" maxLength={2000}
          value={instruction} onChange={(e) => setInstruction(e.target.value)}
          disabled={!readsInstruction} title={readsInstruction ? "blank: the task's own instruction" : note} /></label>
        {!readsInstruction && <span className="muted" id="instruction-note"> {note}</span>}
        {offer && (
          <span id="instruction-left" data-task={leftBehind ?? ""}> your instruction for {leftBehind} stays with it (“{offer}”); this one runs its own.{" "}
            <button type="button" id="instruction-use-mine" onClick={() => { setInstruction(offer); setLeftBehind(null); }}>use my text for {task.name}</button>{" "}
            <button type="button" id="instruction-dismiss" onClick={() => setLeftBehind(null)}>dismiss</button>
          </span>
        )}<br />
        <PlannerFields cat={cat} planner={planner} setPlanner={setPlanner} />
        <label>Segmenter <select name="segmenter" defaultValue={cat.default_segmenter}>{cat.segmenters.map((s) => <option key={s.name} value={s.name} title={s.description}>{segLabel(s)}</option>)}</select></label>
        <label>Robot <select name="embodiment" value={robot} onChange={(e) => setEmbodiment(e.target.value)}><option value="">task default</option>
          {cat.embodiments.filter((x) => task.embodiments.includes(x.name)).map((x) => <option key={x.name} value={x.name}>{x.name}</option>)}</select></label>
        <label>Seed <input type="number" name="seed" defaultValue={0} min={0} className="narrow" /></label>
        <ProtocolField cat={cat} suite={task.suite} />
        <label>Pace <select name="pacing">{PACING.map(([v, l]) => <option key={v} value={v}>{l}</option>)}</select></label>
        <label><input type="checkbox" name="start_paused" /> start paused</label>
        <label title="agentview + wrist video and per-frame labels, for LeRobot export"><input type="checkbox" name="capture" /> record training data</label>
        <details><summary>Run your own plan</summary><PlanEditor text={plan} task={task.instruction} embodiment={checkedOn} onChange={setPlan} onValid={setPlanOk} /></details>
        <button type="submit" disabled={busy || !planOk}>Run</button> <span id="form-error" className="fail">{error}</span>
      </form>
    </section>
  );
}

/** The paper's named evaluation configurations defined on `suite` (none: the field is left out). The server
 * refuses a privileged segmenter or a given plan under one, and says why. */
function ProtocolField({ cat, suite }: { cat: Catalog; suite: string }) {
  const protocols = (cat.protocols ?? []).filter((p) => p.suites.includes(suite));
  if (!protocols.length) return null;
  return (
    <label title="a named evaluation configuration of the paper">Protocol <select name="protocol"><option value="">none</option>
      {protocols.map((p) => <option key={p.name} value={p.name} title={p.description}>{p.name}</option>)}</select></label>
  );
}

function BatchForm({ cat }: { cat: Catalog }) {
  const [planner, setPlanner] = useState(cat.planners[0]?.name ?? "");
  const [suite, setSuite] = useState(Object.keys(cat.suites)[0] ?? "builtin");
  const [error, setError] = useState("");
  const submit = async (e: React.FormEvent<HTMLFormElement>) => {
    e.preventDefault();
    const f = new FormData(e.currentTarget);
    const body: BatchCreate = { suite, trials: Number(f.get("trials")), seed: 0, planner, segmenter: String(f.get("segmenter")), capture: f.get("capture") === "on" } as BatchCreate;
    const tasks = f.getAll("tasks") as string[];
    if (tasks.length) body.tasks = tasks;
    if (f.get("model")) body.model = String(f.get("model"));
    if (f.get("endpoint")) body.endpoint = String(f.get("endpoint"));
    if (f.get("protocol")) body.protocol = String(f.get("protocol"));
    try { go(`#/batch/${(await post<{ id: string }>("/api/batches", body)).id}`); }
    catch (err) { setError((err as Error).message); }
  };
  return (
    <section><h3>New batch</h3>
      <form id="new-batch" onSubmit={submit}>
        <label>Suite <select name="suite" value={suite} onChange={(e) => setSuite(e.target.value)}>{Object.keys(cat.suites).map((s) => <option key={s}>{s}</option>)}</select></label>
        <label>Tasks <select name="tasks" multiple size={4}>{cat.suites[suite].map((t) => <option key={t} value={t}>{t}</option>)}</select></label>
        <label>Trials per task <input type="number" name="trials" defaultValue={2} min={1} max={100} className="narrow" /></label>
        <PlannerFields cat={cat} planner={planner} setPlanner={setPlanner} />
        <label>Segmenter <select name="segmenter" defaultValue={cat.default_segmenter}>{cat.segmenters.map((s) => <option key={s.name} value={s.name}>{segLabel(s)}</option>)}</select></label>
        <ProtocolField cat={cat} suite={suite} />
        <label><input type="checkbox" name="capture" /> record training data</label>
        <button type="submit">Run batch</button> <span id="batch-error" className="fail">{error}</span>
      </form>
    </section>
  );
}

/** The latest trials, refreshed whenever one is queued, starts or ends (the dashboard stream). */
function RecentTrials() {
  const [items, setItems] = useState<TrialSummary[]>([]);
  useEffect(() => {
    const load = () => api<Page<TrialSummary>>("/api/trials?limit=10").then((p) => setItems(p.items)).catch(() => {});
    load();
    const ws = new WebSocket(wsUrl("/api/events"));
    ws.onmessage = load;
    return () => ws.close();
  }, []);
  return <section><h3>Recent trials</h3><div id="recent"><TrialTable items={items} /></div></section>;
}
