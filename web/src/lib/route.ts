// Hash routes: #/ dashboard, #/trial/ID, #/history, #/compare/A/B, #/batches, #/batch/ID.
import { useEffect, useState } from "react";

export function useHash(): string {
  const [hash, setHash] = useState(location.hash || "#/");
  useEffect(() => {
    const on = () => setHash(location.hash || "#/");
    window.addEventListener("hashchange", on);
    return () => window.removeEventListener("hashchange", on);
  }, []);
  return hash;
}

export const go = (hash: string) => { location.hash = hash; };
