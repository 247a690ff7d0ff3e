// SPARK console UI: hash-routed pages over the REST API and the per-trial event WebSocket.
const $ = (sel, el = document) => el.querySelector(sel);
const esc = (s) => String(s ?? "").replace(/[&<>"]/g, (c) => ({ "&": "&amp;", "<": "&lt;", ">": "&gt;", '"': "&quot;" }[c]));
// Beyond loopback the server wants SPARK_API_TOKEN: open the console once as /?token=… and the server swaps it
// for an HttpOnly session cookie, which the browser sends with every request and websocket. No script holds it.
localStorage.removeItem("spark_token"); // where earlier versions kept the token in the clear
const wsUrl = (path) => `${location.protocol === "https:" ? "wss" : "ws"}://${location.host}${path}`;
const api = async (path, opts = {}) => {
  const headers = { "content-type": "application/json" };
  const r = await fetch(path, { headers, ...opts });
  if (!r.ok) throw new Error((await r.json().catch(() => ({}))).detail || r.statusText);
  return r.status === 204 ? null : r.json();
};

// Names and closed sets (planners, segmenters, embodiments, verdicts) come from the server's one catalog.
let catalogCache = null;
const catalog = async () => (catalogCache ??= await api("/api/catalog"));
const options = (entries, label = (e) => e.name) => entries.map((e) => `<option value="${esc(e.name)}">${esc(label(e))}</option>`).join("");
const segLabel = (s) => `${s.name}${s.privileged ? " (privileged)" : ""}`;

async function dashboard(view) {
  const cat = await catalog();
  const tasks = cat.tasks;
  view.innerHTML = `
    <section><h3>New trial</h3>
      <form id="new-trial">
        <label>Task <select name="task">${tasks.map((t) => `<option value="${t.name}">${t.name}${t.suite === "builtin" ? "" : ` (${t.suite})`}</option>`).join("")}</select></label>
        <label>Instruction <input type="text" name="instruction" placeholder="default: the task's own"></label><br>
        <label>Planner <select name="planner">${options(cat.planners)}</select></label>
        <label>Model <input type="text" name="model" placeholder="planner default" style="width:10em"></label>
        <label title="LLM endpoints the operator configured (spark.yaml endpoints:)">Endpoint <select name="endpoint"><option value="">vendor default</option>${options(cat.endpoints, (e) => `${e.name} (${e.planner})`)}</select></label>
        <label>Segmenter <select name="segmenter">${options(cat.segmenters, segLabel)}</select></label>
        <label>Robot <select name="embodiment"><option value="">task default</option>${options(cat.embodiments)}</select></label>
        <label>Seed <input type="number" name="seed" value="0" min="0" style="width:5em"></label>
        <label><input type="checkbox" name="start_paused"> start paused</label>
        <label title="agentview + wrist video and per-frame labels, for LeRobot export"><input type="checkbox" name="capture"> record training data</label>
        <button type="submit">Run</button> <span id="form-error" class="fail"></span>
      </form></section>
    <section><h3>New batch</h3>
      <form id="new-batch">
        <label>Tasks <select name="tasks" multiple size="4">${tasks.map((t) => `<option value="${t.name}">${t.name}</option>`).join("")}</select></label>
        <label>Trials per task <input type="number" name="trials" value="2" min="1" max="100" style="width:5em"></label>
        <label>Planner <select name="planner">${options(cat.planners)}</select></label>
        <label>Segmenter <select name="segmenter">${options(cat.segmenters, segLabel)}</select></label>
        <label><input type="checkbox" name="capture"> record training data</label>
        <button type="submit">Run batch</button> <span id="batch-error" class="fail"></span>
      </form></section>
    <section><h3>Recent trials</h3><div id="recent">loading…</div></section>`;
  $("#new-trial").onsubmit = async (e) => {
    e.preventDefault();
    const f = new FormData(e.target);
    const body = { task: f.get("task"), planner: f.get("planner"), segmenter: f.get("segmenter"),
                   seed: Number(f.get("seed")), start_paused: f.get("start_paused") === "on", capture: f.get("capture") === "on" };
    if (f.get("instruction")) body.instruction = f.get("instruction");
    if (f.get("embodiment")) body.embodiment = f.get("embodiment");
    if (f.get("model")) body.model = f.get("model");
    if (f.get("endpoint")) body.endpoint = f.get("endpoint");
    try { const r = await api("/api/trials", { method: "POST", body: JSON.stringify(body) }); location.hash = `#/trial/${r.id}`; }
    catch (err) { $("#form-error").textContent = err.message; }
  };
  $("#new-batch").onsubmit = async (e) => {
    e.preventDefault();
    const f = new FormData(e.target);
    const body = { trials: Number(f.get("trials")), planner: f.get("planner"), segmenter: f.get("segmenter"),
                   capture: f.get("capture") === "on" };
    const chosen = f.getAll("tasks");
    if (chosen.length) body.tasks = chosen;
    try { const r = await api("/api/batches", { method: "POST", body: JSON.stringify(body) }); location.hash = `#/batch/${r.id}`; }
    catch (err) { $("#batch-error").textContent = err.message; }
  };
  const refresh = async () => { $("#recent").innerHTML = trialTable((await api("/api/trials?limit=10")).items); };
  await refresh();
  const ws = new WebSocket(wsUrl("/api/events"));
  ws.onmessage = () => { if (location.hash === "" || location.hash === "#/") refresh(); else ws.close(); };
}

function trialTable(items, selectable = false) {
  return `<table><tr>${selectable ? "<th></th>" : ""}<th>trial</th><th>task</th><th>status</th><th>verdict</th><th>planner</th><th>segmenter</th><th>seed</th><th>wall s</th><th>cost $</th><th>instruction</th></tr>
    ${items.map((t) => `<tr>${selectable ? `<td><input type="checkbox" class="pick" value="${esc(t.id)}"></td>` : ""}<td><a href="#/trial/${t.id}">${esc(t.id)}</a></td><td>${esc(t.task)}</td><td>${esc(t.status)}</td>
      <td class="${t.success ? "ok" : "fail"}">${esc(t.verdict ?? "")}</td><td>${esc(t.planner)}</td><td>${esc(t.segmenter)}</td><td>${t.seed}</td>
      <td>${t.wall_time_s ?? ""}</td><td>${(t.cost_usd ?? 0).toFixed(4)}</td><td>${esc(t.instruction)}</td></tr>`).join("")}</table>`;
}

async function exportDataset(body, out) {
  out.textContent = "exporting…";
  try {
    const r = await api("/api/exports", { method: "POST", body: JSON.stringify(body) });
    out.innerHTML = `${r.episodes} episode(s), ${r.frames} frames, ${(r.bytes / 1e6).toFixed(1)} MB
      <a id="export-download" href="${r.download}">download (zip)</a>${r.skipped.length ? ` · ${r.skipped.length} skipped (${esc(r.skipped[0].reason)})` : ""}`;
  } catch (err) { out.innerHTML = `<span class="fail">${esc(err.message)}</span>`; }
}

async function history(view) {
  view.innerHTML = `<section><h3>History</h3>
    <form id="filters"><label>Search <input type="text" name="q"></label>
      <label>Status <select name="status"><option value="">any</option><option>done</option><option>running</option><option>queued</option><option>interrupted</option></select></label>
      <label>Verdict <select name="verdict"><option value="">any</option>${(await catalog()).verdict.map((v) => `<option>${esc(v)}</option>`).join("")}</select></label>
      <label>Sort <select name="sort"><option>-created_at</option><option>created_at</option><option>-wall_time_s</option><option>-cost_usd</option><option>task</option><option>verdict</option><option>-seed</option></select></label>
      <button>Filter</button></form>
    <p><button id="export-selected">Export selected (LeRobot)</button> <label><input type="checkbox" id="export-failures"> include failures</label>
      <span id="export-result"></span></p><div id="rows"></div></section>`;
  const load = async () => {
    const f = new FormData($("#filters"));
    const params = new URLSearchParams([...f.entries()].filter(([, v]) => v));
    const page = await api(`/api/trials?limit=100&${params}`);
    $("#rows").innerHTML = `<p>${page.total} trial(s)</p>` + trialTable(page.items, true);
  };
  $("#export-selected").onclick = () => {
    const ids = [...document.querySelectorAll("#rows .pick:checked")].map((c) => c.value);
    exportDataset({ trial_ids: ids, success_only: !$("#export-failures").checked }, $("#export-result"));
  };
  $("#filters").onsubmit = (e) => { e.preventDefault(); load(); };
  load();
}

function renderTree(node, path, state) {
  if (node.primitive) {
    const params = Object.entries(node.params || {}).map(([k, v]) => `${k}=${v}`).join(", ");
    const st = state.status[path] || "pending";
    const bp = state.breakpoints.has(path) ? " breakpoint" : "";
    const retries = state.retries[path] ? `<span class="retries">retries ${state.retries[path]}</span>` : "";
    return `<li><span class="node ${st}${bp}" data-path="${path}" title="${path} (click: breakpoint)">${node.primitive}(${esc(params)})</span>${retries}</li>`;
  }
  const st = state.status[path] || "pending";
  return `<li><span class="node ${st}" data-path="${path}">${node.type}${node.arm ? " [" + node.arm + "]" : ""}</span>
    <ul>${node.children.map((c, i) => renderTree(c, `${path}.children[${i}]`, state)).join("")}</ul></li>`;
}

function timeline(trial) {
  // one row per primitive type, one bar per node run, coloured by outcome (the "score" view)
  const nodes = Object.values(trial.nodes || {}).filter((n) => n.started_t !== null && n.finished_t !== null && !["sequence", "parallel", "fallback"].includes(n.kind));
  if (!nodes.length) return "";
  const kinds = [...new Set(nodes.map((n) => n.kind))];
  const t1 = Math.max(...nodes.map((n) => n.finished_t)) || 1;
  const W = 700, H = 22 * kinds.length + 20;
  const bars = nodes.map((n) => `<rect x="${130 + (n.started_t / t1) * (W - 140)}" y="${kinds.indexOf(n.kind) * 22 + 4}"
      width="${Math.max(2, ((n.finished_t - n.started_t) / t1) * (W - 140))}" height="16" fill="${n.status === "succeeded" ? "#4caf50" : "#e53935"}"><title>${n.path} ${(n.finished_t - n.started_t).toFixed(3)} s</title></rect>`).join("");
  const labels = kinds.map((k, i) => `<text x="4" y="${i * 22 + 16}" font-size="12">${k}</text>`).join("");
  return `<svg id="timeline" width="${W}" height="${H}">${labels}${bars}</svg>`;
}

async function trialPage(view, id) {
  const cat = await catalog();
  let trial = await api(`/api/trials/${id}`);
  const state = { status: {}, retries: {}, breakpoints: new Set(), events: [] };
  view.innerHTML = `<section><h3>Trial ${esc(id)}</h3><div id="summary"></div>
      <div id="controls"><button id="pause">Pause</button><button id="step">Step</button><button id="resume">Resume</button><button id="abort">Abort</button>
      <a id="download" href="/api/trials/${id}" download="${id}.json">Download trace (JSON)</a>
      <button id="replay" title="replay the recorded trial in the 3D view">Replay in 3D</button></div></section>
    <section><h3>Behavior tree</h3><div class="tree" id="tree">waiting for the plan…</div></section>
    <section><h3>3D view</h3><div id="viser"></div></section>
    <section><h3>Timeline</h3><div id="score"></div></section>
    <section><h3>Detections</h3><div id="detections"></div></section>
    <section><h3>Groundings</h3><div id="groundings"></div></section>
    <section><h3>Events</h3><div id="log"></div></section>`;
  const control = (action, extra = {}) => api(`/api/trials/${id}/control`, { method: "POST", body: JSON.stringify({ action, ...extra }) }).catch((e) => alert(e.message));
  for (const a of ["pause", "step", "resume", "abort"]) $("#" + a).onclick = () => control(a);
  $("#replay").onclick = () => api(`/api/trials/${id}/replay`, { method: "POST" }).catch((e) => alert(e.message));
  const draw = () => {
    $("#summary").innerHTML = `<p>${esc(trial.task)} · “${esc(trial.instruction)}” · planner ${esc(trial.planner)} · segmenter ${esc(trial.segmenter)}${trial.protocol?.privileged ? " (privileged)" : ""}
      · status <b id="status">${esc(trial.status)}</b>${trial.verdict ? ` · <b class="${trial.success ? "ok" : "fail"}" id="verdict">${esc(trial.verdict)}</b>` : ""}
      ${trial.reason ? " · " + esc(trial.reason) : ""}</p>`;
    if (trial.plan_tree) $("#tree").innerHTML = `<ul>${renderTree(trial.plan_tree.tree, "tree", state)}</ul>`;
    $("#log").textContent = state.events.map((e) => `${(e.t ?? 0).toFixed(3)}  ${e.kind.padEnd(9)} ${e.node_path ?? ""} ${JSON.stringify(e.detail ?? {})}`).join("\n");
    $("#score").innerHTML = timeline(trial);
    $("#detections").innerHTML = (trial.artifacts || []).filter((a) => a.kind === "detections").map((a) =>
      `<figure style="display:inline-block;margin:0 1em 0 0"><img src="/api/trials/${id}/artifacts/${a.name}" width="400" alt="${esc(a.camera)}"><figcaption>${esc(a.camera)}</figcaption></figure>`).join("");
    $("#groundings").innerHTML = (trial.groundings || []).map((g) => `<div>${esc(g.label)}: ${Object.entries(g.cameras || {}).map(([c, s]) => `${c} → ${esc(s.chosen ?? "none")}`).join(", ")}</div>`).join("");
  };
  $("#tree").onclick = (e) => {
    const path = e.target.dataset.path;
    if (!path) return;
    state.breakpoints.has(path) ? state.breakpoints.delete(path) : state.breakpoints.add(path);
    control("breakpoints", { breakpoints: [...state.breakpoints] });
    draw();
  };
  const apply = (ev) => {
    if (ev.kind === "closed") return;
    state.events.push(ev);
    const p = ev.node_path;
    const nodeStatus = cat.event_node_status[ev.kind]; // the engine's own mapping (GET /api/catalog)
    if (nodeStatus) state.status[p] = nodeStatus;
    if (ev.kind === "retrying") state.retries[p] = (state.retries[p] || 0) + 1;
  };
  draw();
  api("/api/viser").then((v) => {
    // Same origin: viser's client page from /viser/, its websocket relayed by the console at /viser.
    $("#viser").innerHTML = v.enabled ? `<iframe id="viser-frame" src="${v.path}" width="100%" height="420" style="border:0"></iframe>`
      : "3D view disabled (SPARK_VISER=0)";
  }).catch(() => {});
  const ws = new WebSocket(wsUrl(`/api/trials/${id}/events`));
  ws.onmessage = async (msg) => {
    const ev = JSON.parse(msg.data);
    apply(ev);
    if (!trial.plan_tree || ev.kind === "closed" || ev.kind === "paused") trial = await api(`/api/trials/${id}`);
    draw();
  };
  ws.onclose = async () => { await new Promise((r) => setTimeout(r, 300)); trial = await api(`/api/trials/${id}`); draw(); };
}

async function batchPage(view, id) {
  view.innerHTML = `<section><h3>Batch ${esc(id)}</h3><progress id="batch-progress" max="1" value="0" style="width:30em"></progress>
    <span id="batch-count"></span> <button id="batch-cancel">Cancel</button>
    <a id="batch-results-csv" href="/api/batches/${id}/results.csv">results (CSV)</a>
    <a id="batch-trials-csv" href="/api/batches/${id}/trials.csv">trials (CSV)</a>
    <button id="batch-export">Export successes (LeRobot)</button> <span id="export-result"></span><div id="batch-table"></div></section>`;
  $("#batch-export").onclick = () => exportDataset({ batch: id }, $("#export-result"));
  $("#batch-cancel").onclick = () => api(`/api/batches/${id}/cancel`, { method: "POST" });
  const pct = (x) => (x === null ? "" : (100 * x).toFixed(1) + " %");
  for (;;) {
    const b = await api(`/api/batches/${id}`);
    $("#batch-progress").max = b.progress.total;
    $("#batch-progress").value = b.progress.done;
    $("#batch-count").textContent = `${b.progress.done} / ${b.progress.total} · ${b.status}`;
    $("#batch-table").innerHTML = `<table><tr><th>task</th><th>done</th><th>success</th><th>95 % CI</th></tr>${b.results.map((r) =>
      `<tr><td>${esc(r.task)}</td><td>${r.done}/${r.total}</td><td>${pct(r.success_rate)}</td><td>${pct(r.ci95[0])} – ${pct(r.ci95[1])}</td></tr>`).join("")}</table>`;
    if (b.status !== "running" || location.hash !== `#/batch/${id}`) break;
    await new Promise((r) => setTimeout(r, 500));
  }
}

async function route() {
  const view = $("#view");
  const hash = location.hash || "#/";
  try {
    if (hash.startsWith("#/trial/")) await trialPage(view, decodeURIComponent(hash.slice(8)));
    else if (hash.startsWith("#/batch/")) await batchPage(view, decodeURIComponent(hash.slice(8)));
    else if (hash === "#/history") await history(view);
    else await dashboard(view);
  } catch (err) { view.innerHTML = `<section class="fail">${esc(err.message)}</section>`; }
}
window.addEventListener("hashchange", route);
route();
