// The one catalog (GET /api/catalog): every name and closed set the UI shows comes from here.
import { useEffect, useState } from "react";
import { api } from "./client";
import type { Catalog } from "./types";

let cached: Promise<Catalog> | null = null;
export const loadCatalog = () => (cached ??= api<Catalog>("/api/catalog"));

export function useCatalog(): Catalog | null {
  const [cat, setCat] = useState<Catalog | null>(null);
  useEffect(() => { loadCatalog().then(setCat); }, []);
  return cat;
}
