// The one catalog (GET /api/catalog): every name and closed set the UI shows comes from here.
import { useEffect, useState } from "react";
import { api } from "./client";
import type { Catalog } from "./types";

let cached: Promise<Catalog> | null = null;
export const loadCatalog = () => (cached ??= api<Catalog>("/api/catalog"));

/** Whether a trial's perception read simulator state: what its record says once it has started, else what the
 * catalog says of its segmenter (keypoint sources included); null when neither knows. */
export function isPrivileged(
  cat: Catalog | null, t: { segmenter: string; protocol?: { privileged?: unknown } | null },
): boolean | null {
  const recorded = t.protocol?.privileged;
  if (typeof recorded === "boolean") return recorded;
  const entry = cat?.segmenters.find((s) => s.name === t.segmenter);
  return entry ? entry.privileged : null;
}

export const PRIVILEGED_NOTE = "privileged: perception read simulator state (ids, names or poses), not only the cameras";

export function useCatalog(): Catalog | null {
  const [cat, setCat] = useState<Catalog | null>(null);
  useEffect(() => { loadCatalog().then(setCat); }, []);
  return cat;
}
