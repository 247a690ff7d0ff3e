// A trial's verdict (the catalog's closed set): green only for success.
export function VerdictBadge({ verdict, id }: { verdict: string | null | undefined; id?: string }) {
  if (!verdict) return null;
  return <b id={id} className={`verdict ${verdict === "success" ? "ok" : "fail"}`} data-verdict={verdict}>{verdict}</b>;
}
