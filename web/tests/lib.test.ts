// Unit tests of the workspace's pure logic (run by `npm test`: esbuild bundles, node's test runner runs).
import assert from "node:assert/strict";
import { test } from "node:test";
import type { Catalog, Trial, TrialEvent } from "../src/api/types";
import { diffLines, firstDivergence } from "../src/lib/compare";
import { groundingOutcome } from "../src/lib/groundingOutcome";
import { activeWall, anchors, leafAnchors, treeStateAt, unpaused, wallToSim, withoutPauses } from "../src/lib/trialTime";
import { localTime } from "../src/lib/localTime";
import { linePaths } from "../src/lib/yamlPaths";

const PLAN = `task: t
tree:
  type: sequence
  children:
  - type: pick
    params:
      lift_height: 5
  - type: parallel
    children:
      - type: a
      - type: b
        params: {x: 1}`;

test("each line of a plan has the path the validator names", () => {
  assert.deepEqual(linePaths(PLAN), [
    "task", "tree", "tree.type", "tree.children", "tree.children[0].type", "tree.children[0].params",
    "tree.children[0].params.lift_height", "tree.children[1].type", "tree.children[1].children",
    "tree.children[1].children[0].type", "tree.children[1].children[1].type", "tree.children[1].children[1].params",
  ]);
});

test("the plan diff keeps common lines and marks the rest", () => {
  const d = diffLines(["a", "b", "c"], ["a", "x", "c"]);
  assert.deepEqual(d.map((x) => x.op + x.line), [" a", "-b", "+x", " c"]);
});

const node = (path: string, kind: string, s: number, f: number, sim: number, status = "succeeded") =>
  ({ path, kind, arm: null, status, attempts: 1, retries: 0, started_t: s, finished_t: f, sim_time_s: sim, failure: null, reason: "", recoveries: [] });

const trial = (over: Partial<Trial> = {}): Trial => ({
  id: "x", created_at: null, status: "done", task: "t", instruction: "", seed: 0, planner: "p", segmenter: "s",
  outcome: "", success: true, verdict: "success", failure: null, failed_node: null, reason: "", wall_time_s: 3,
  sim_time_s: 4, cost_usd: 0, batch_id: null, protocol: {}, plan_text: "", plan_tree: null, groundings: [], artifacts: [],
  events: [],
  nodes: { tree: node("tree", "sequence", 0, 3, 4), "tree.children[0]": node("tree.children[0]", "pick", 0, 1, 1), "tree.children[1]": node("tree.children[1]", "place", 2, 3, 1) },
  ...over,
});

test("without events' t_sim, wall time maps to simulated time inside each leaf, ending at the trial's total", () => {
  const a = anchors(trial(), [{ t: 0, kind: "started", node_path: "tree" }], 3);
  assert.deepEqual(a, leafAnchors(trial()));
  assert.equal(wallToSim(a, 0), 0);
  assert.equal(wallToSim(a, 3), 4);
  assert.ok(wallToSim(a, 0.5) > 0 && wallToSim(a, 0.5) < wallToSim(a, 2.5));
});

const ev = (t: number, kind: string, node_path: string): TrialEvent => ({ t, kind, node_path });

test("the cursor's simulated time is the events' own t_sim, then the trial's simulated end", () => {
  const evs: TrialEvent[] = [
    { t: 0, t_sim: 10, kind: "started", node_path: "tree" },
    { t: 1, t_sim: 12, kind: "succeeded", node_path: "tree.children[0]" },
    { t: 1, t_sim: 12.5, kind: "started", node_path: "tree.children[1]" },
    { t: 2, t_sim: 13, kind: "succeeded", node_path: "tree" },
  ];
  const a = anchors(trial({ sim_time_s: 13.5 }), evs, 3);
  assert.deepEqual(a, [{ wall: 0, sim: 10 }, { wall: 1, sim: 12.5 }, { wall: 2, sim: 13 }, { wall: 3, sim: 13.5 }]);
  assert.equal(wallToSim(a, 0.5), 11.25);
  assert.equal(wallToSim(a, 2), 13);
  assert.equal(wallToSim(a, 3), 13.5);
});

test("paused spans are cut out of the clock and of the wall time", () => {
  const events = [ev(0, "started", "tree"), ev(0.1, "paused", "tree.children[0]"), ev(5.1, "started", "tree.children[0]"), ev(6, "succeeded", "tree")];
  assert.ok(Math.abs(unpaused([[0.1, 5.1]], 6) - 1) < 1e-9);
  assert.ok(Math.abs(unpaused([[0.1, 5.1]], 3) - 0.1) < 1e-9); // inside a pause: where the pause began
  assert.ok(Math.abs(activeWall(events, 6) - 1) < 1e-9);
  const cut = withoutPauses(trial({ events }), events);
  assert.deepEqual(cut.events.map((e) => +e.t.toFixed(6)), [0, 0.1, 0.1, 1]);
});

const CAT = { event_node_status: { started: "running", succeeded: "succeeded", failed: "failed", paused: "paused" } } as unknown as Catalog;

test("the tree at a time follows the events; at the end an abort leaves no node running", () => {
  const events = [ev(0, "started", "tree"), ev(0.1, "started", "tree.children[0]"), ev(1, "succeeded", "tree.children[0]"), ev(1.2, "retrying", "tree.children[1]")];
  const mid = treeStateAt(CAT, trial(), events, 0.5, false);
  assert.equal(mid["tree.children[0]"].status, "running");
  assert.equal(treeStateAt(CAT, trial(), events, 2, false)["tree.children[1]"].retries, 1);
  const aborted = trial({ verdict: "aborted", nodes: { tree: node("tree", "sequence", 0, 3, 4, "running") } });
  assert.equal(treeStateAt(CAT, aborted, events, 3, true).tree.status, "aborted");
});

test("the first divergence names the node and both sides", () => {
  const b = trial({ nodes: { ...trial().nodes, "tree.children[1]": node("tree.children[1]", "place", 2, 3, 1, "failed") } });
  assert.match(firstDivergence(trial(), b), /tree.children\[1\] \(place\): A succeeded, B failed/);
  assert.match(firstDivergence(trial(), trial()), /^none/);
});

test("an API time is shown in the browser's time zone, one without an offset read as UTC", () => {
  const zone = process.env.TZ;
  process.env.TZ = "Asia/Kolkata"; // UTC+05:30, no daylight saving
  try {
    assert.equal(localTime("2026-01-02T03:04:05.123456+00:00"), "2026-01-02 08:34:05");
    assert.equal(localTime("2026-01-02T03:04:05Z"), "2026-01-02 08:34:05");
    assert.equal(localTime("2026-01-02T03:04:05.5-02:00"), "2026-01-02 10:34:05");
    assert.equal(localTime("2026-01-02T03:04:05.123456"), "2026-01-02 08:34:05"); // naive: UTC, as stored
    assert.equal(localTime("2026-12-31T23:59:59+00:00"), "2027-01-01 05:29:59"); // the date moves too
    assert.equal(localTime(null), "");
    assert.equal(localTime("soon"), "soon");
  } finally {
    if (zone === undefined) delete process.env.TZ; else process.env.TZ = zone;
  }
});

test("a grounding refused as ambiguous says so; one that found nothing, that it kept no keypoint", () => {
  assert.equal(groundingOutcome({ keypoint: { position_m: [0, 0, 0] } }), "");
  assert.equal(groundingOutcome({ keypoint: null, several: 2 }), " · ambiguous: one camera saw one, another 2");
  assert.equal(groundingOutcome({ keypoint: null }), " · no keypoint");
});
