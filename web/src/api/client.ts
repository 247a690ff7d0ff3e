// Typed calls to the console's REST API (request/response types generated from its OpenAPI document).
import type { components } from "./schema";

export type Schemas = components["schemas"];
export type TrialCreate = Schemas["TrialCreate"];
export type BatchCreate = Schemas["BatchCreate"];
export type Control = Schemas["Control"];
export type PlanValidation = Schemas["PlanValidation"];

export class ApiError extends Error {
  constructor(readonly status: number, message: string) {
    super(message);
  }
}

/** JSON from `path`; a non-2xx answer throws ApiError with the server's `detail` (what was wrong). */
export async function api<T>(path: string, init: RequestInit & { json?: unknown } = {}): Promise<T> {
  const { json, ...rest } = init;
  const r = await fetch(path, {
    ...rest,
    headers: { "content-type": "application/json" },
    body: json === undefined ? rest.body : JSON.stringify(json),
  });
  if (!r.ok) {
    const body = await r.json().catch(() => ({}));
    const detail = body.detail;
    const message = typeof detail === "string" ? detail
      : Array.isArray(detail) ? detail.map((d: { loc?: unknown[]; msg?: string }) => `${(d.loc ?? []).slice(1).join(".")}: ${d.msg}`).join("; ")
      : r.statusText;
    throw new ApiError(r.status, message);
  }
  return (r.status === 204 ? null : await r.json()) as T;
}

export const post = <T>(path: string, json?: unknown) => api<T>(path, { method: "POST", json });

export const wsUrl = (path: string) => `${location.protocol === "https:" ? "wss" : "ws"}://${location.host}${path}`;
