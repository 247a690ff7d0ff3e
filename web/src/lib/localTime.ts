// Times the API serves (ISO 8601 in UTC with an explicit offset: 2026-11-28T11:51:12.352682+00:00) shown in the
// browser's own time zone.

/** "YYYY-MM-DD HH:MM:SS" in local time for an ISO 8601 instant; one without an offset (a record served before the
 * API gave one) is read as UTC, which is what the server stores; text that is not a time is shown as it is. */
export function localTime(iso: string | null | undefined): string {
  if (!iso) return "";
  const text = iso.trim().replace(" ", "T").replace(/(\.\d{3})\d+/, "$1"); // Date parses milliseconds, not micro
  const d = new Date(/(Z|[+-]\d\d:?\d\d)$/i.test(text) ? text : `${text}Z`);
  if (Number.isNaN(d.getTime())) return iso;
  const p = (n: number) => String(n).padStart(2, "0");
  return `${d.getFullYear()}-${p(d.getMonth() + 1)}-${p(d.getDate())} ${p(d.getHours())}:${p(d.getMinutes())}:${p(d.getSeconds())}`;
}
