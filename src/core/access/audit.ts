// The audit log's areas (the first word of every action) and its details in
// plain lines, shared by the admin.auditLog filter and the Audit log page.

export const AUDIT_AREAS = [
  { value: "study", label: "Studies" },
  { value: "member", label: "Study members" },
  { value: "participant", label: "Participants and consent" },
  { value: "user", label: "Accounts" },
  { value: "plugins", label: "Robot plugins" },
] as const;

export type AuditArea = (typeof AUDIT_AREAS)[number]["value"];
export const AUDIT_AREA_VALUES = AUDIT_AREAS.map((a) => a.value) as [AuditArea, ...AuditArea[]];

const MAX_LINES = 12;

function scalar(value: unknown): string {
  if (value === null || value === undefined) return "none";
  if (typeof value === "boolean") return value ? "yes" : "no";
  return String(value);
}

/** Nested details become `a.b: value` lines; a list of plain values stays on one line. */
function flatten(prefix: string, value: unknown, out: Array<[string, string]>) {
  if (Array.isArray(value)) {
    if (value.length === 0) out.push([prefix, "none"]);
    else if (value.every((v) => v === null || typeof v !== "object")) out.push([prefix, value.map(scalar).join(", ")]);
    else value.forEach((v, i) => flatten(`${prefix} ${i + 1}`, v, out));
  } else if (value !== null && typeof value === "object") {
    const entries = Object.entries(value);
    if (entries.length === 0) out.push([prefix, "none"]);
    for (const [k, v] of entries) flatten(prefix ? `${prefix}.${k}` : k, v, out);
  } else out.push([prefix, scalar(value)]);
}

/**
 * An entry's details as `key: value` pairs a person can read; a long list
 * (a sync that changed many robots) ends with how many more there are.
 */
export function detailLines(details: unknown): Array<[string, string]> {
  if (details === null || typeof details !== "object" || Object.keys(details).length === 0) return [];
  const out: Array<[string, string]> = [];
  flatten("", details, out);
  if (out.length <= MAX_LINES) return out;
  return [...out.slice(0, MAX_LINES - 1), ["…", `${out.length - MAX_LINES + 1} more`]];
}
