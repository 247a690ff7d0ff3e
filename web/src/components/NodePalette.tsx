// The primitives the grammar offers (GET /api/grammar, generated from the registry), grouped by tier; clicking one
// appends a leaf with its required slots to the plan being edited. The post-condition is in the tooltip.
import { useEffect, useState } from "react";
import { api } from "../api/client";

interface Slot { name: string; type: string; required: boolean; default: unknown; unit: string; values: unknown[] }
interface Primitive { name: string; tier: string; description: string; postcondition: string; slots: Slot[] }

const SKELETON = (task: string) => `task: ${task}\ntree:\n  type: sequence\n  children:\n`;

/** `text` with a leaf for `p` appended (a skeleton first if there is no plan yet). */
export function appendLeaf(text: string, p: Primitive, task: string): string {
  const params = p.slots.filter((s) => s.required).map((s) => `${s.name}: ${s.type === "label" ? "OBJECT" : String(s.values[0] ?? s.default ?? "")}`);
  const base = text.trim() ? text.replace(/\s*$/, "\n") : SKELETON(task);
  return `${base}    - type: ${p.name}\n` + (params.length ? `      params: {${params.join(", ")}}\n` : "");
}

export function NodePalette({ text, task, onChange }: { text: string; task: string; onChange: (t: string) => void }) {
  const [prims, setPrims] = useState<Primitive[]>([]);
  useEffect(() => { api<{ primitives: Primitive[] }>("/api/grammar").then((g) => setPrims(g.primitives)).catch(() => {}); }, []);
  const tiers = [...new Set(prims.map((p) => p.tier))];
  return (
    <div className="palette" id="node-palette">
      {tiers.map((tier) => (
        <div key={tier}><span className="muted">{tier}:</span>{" "}
          {prims.filter((p) => p.tier === tier).map((p) => (
            <button type="button" key={p.name} data-primitive={p.name} title={`${p.description}\npost-condition: ${p.postcondition}`}
              onClick={() => onChange(appendLeaf(text, p, task))}>{p.name}</button>))}
        </div>))}
    </div>
  );
}
