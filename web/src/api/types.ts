// Shapes of what the API returns as free-form JSON (trial records, the catalog, batches): the OpenAPI document
// types these as objects, so they are spelt out here from the store's record (spark_core/trace/store.py).

export interface CatalogEntry { name: string; description: string }
export interface Planner extends CatalogEntry {
  offline: boolean; needs_model: boolean; default_model: string | null;
  /** false: the planner does not read the trial's instruction (the server refuses one that differs from the task's) */
  reads_instruction: boolean;
}
export interface Segmenter extends CatalogEntry { privileged: boolean; cameras: boolean; needs: string }
/** `arms`: the names a plan's arm tags may use on it; `suite`: the benchmark suite whose env brings this robot (it runs
 * that suite's tasks only), null for a set-up the scene builder puts any task that fits on. */
export interface Embodiment extends CatalogEntry { arms: string[]; suite: string | null }
/** A named evaluation configuration of the paper (spark_core/bench/protocols.py). */
export interface Protocol extends CatalogEntry { suites: string[]; wording: string; adaptive: boolean }
export interface Endpoint { name: string; planner: string; [k: string]: unknown }
export interface Task {
  name: string; suite: string; instruction: string; predicate: string; embodiments: string[];
  has_reference_plan: boolean; max_sim_s: number; tags: string[]; objects: string[];
}
export interface Catalog {
  planners: Planner[]; segmenters: Segmenter[];
  /** what a trial perceives with when the form or request names no segmenter (the camera-only `learned`) */
  default_segmenter: string;
  embodiments: Embodiment[]; endpoints: Endpoint[];
  protocols: Protocol[]; suites: Record<string, string[]>; tasks: Task[];
  verdict: string[]; node_status: string[]; event_kind: string[]; tree_status: string[];
  event_node_status: Record<string, string>;
}

/** `t`: wall seconds since the trial started; `t_sim`: the world's simulated seconds at publication (null on
 * records stored before the store's revision 0009); `wall_s`: the Unix time of publication (live events). */
export interface TrialEvent { seq?: number; t: number; t_sim?: number | null; wall_s?: number;
  /** the server's Unix time when it sent the event over the live stream (absent in stored records) */
  sent_s?: number; node_path: string; kind: string; detail?: Record<string, unknown> }

export interface NodeRecord {
  path: string; kind: string; arm: string | null; status: string; attempts: number; retries: number;
  started_t: number | null; finished_t: number | null; sim_time_s: number | null;
  failure: string | null; reason: string; recoveries: unknown[]; duration_s?: number | null;
}

export interface Candidate { prompt: string; n_detections: number; best_score: number | null; verdict: string }
export interface Grounding {
  label: string; t_sim_s: number | null;
  cameras: Record<string, { label: string; chosen: string | null; candidates: Candidate[] }>;
  keypoint?: { position_m: number[]; score?: number; source?: string } | null;
  several?: number;  // refused as ambiguous: one camera singled the label out, another saw this many
}

/** A file the trial kept. kind `grounding`: the annotated detection image of one grounding (`grounding` is its
 * index in the trial's groundings) through one camera; kind `detections`: one per camera, of the last frame. */
export interface Artifact {
  name: string; kind: string; camera?: string | null; grounding?: number; label?: string; t_sim_s?: number | null;
}

export interface PlanNode {
  type?: string; primitive?: string; arm?: string | null; params?: Record<string, unknown>; children?: PlanNode[];
}

export interface TrialSummary {
  id: string; created_at: string | null; status: string; task: string; instruction: string; seed: number;
  planner: string; segmenter: string; outcome: string; success: boolean | null; verdict: string | null;
  failure: string | null; failed_node: string | null; reason: string; wall_time_s: number | null;
  sim_time_s: number | null; cost_usd: number | null; batch_id: string | null;
  protocol?: Record<string, unknown> & { privileged?: boolean } | null;
  /** frames of its training-data capture (what a LeRobot export takes); null: none (list summaries only) */
  training_frames?: number | null;
}

export interface Trial extends TrialSummary {
  protocol: Record<string, unknown> & { privileged?: boolean; config?: Record<string, unknown> };
  plan_text: string; plan_tree: { task: string; tree: PlanNode } | null;
  nodes: Record<string, NodeRecord>; events: TrialEvent[]; groundings: Grounding[];
  artifacts: Artifact[];
  control_state?: string; breakpoints?: string[]; usage?: Record<string, unknown>;
}

export interface Page<T> { total: number; limit: number; offset: number; items: T[] }

export interface BatchSummary {
  id: string; created_at: string; status: string; spec: Record<string, unknown>;
  progress: { done: number; total: number; successes?: number };
}
/** `success_rate` and its 95 % Wilson interval `ci95` are over the judged trials: both null while there is none */
export interface BatchResult { task: string; done: number; total: number; successes: number; success_rate: number | null; ci95: [number, number] | null }
export interface Batch extends BatchSummary { trials: TrialSummary[]; results: BatchResult[] }
