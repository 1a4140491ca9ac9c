// The audit log's areas (the first word of every action) and its details in
// plain lines, shared by the admin.auditLog filter and the Audit log page.

export const AUDIT_AREAS = [
  { value: "study", label: "Studies" },
  { value: "member", label: "Study members" },
  { value: "participant", label: "Participants and consent" },
  { value: "user", label: "Accounts" },
  { value: "plugins", label: "Robot plugins" },
  { value: "robot", label: "Robots" },
  { value: "token", label: "Access tokens" },
] as const;

export type AuditArea = (typeof AUDIT_AREAS)[number]["value"];
export const AUDIT_AREA_VALUES = AUDIT_AREAS.map((a) => a.value) as [AuditArea, ...AuditArea[]];

// What each action did, in the researcher's words; an action not listed here shows as it is.
const ACTION_WORDS: Record<string, string> = {
  "study.create": "created the study",
  "study.update": "changed the study",
  "study.blind.lifted.conditions": "showed wizards the conditions",
  "study.blind.lifted.results": "opened the results",
  "member.add": "added a member",
  "member.role": "changed a member's role",
  "member.remove": "removed a member",
  "participant.assign": "assigned a condition",
  "participant.consent.given": "recorded consent given",
  "participant.consent.declined": "recorded consent declined",
  "participant.consent.withdrawn": "recorded a withdrawal",
  "participant.consent.pending": "set consent back to pending",
  "participant.consent.reinstated": "reinstated a participant",
  "user.create": "created an account",
  "user.role": "changed an account's role",
  "user.disable": "disabled an account",
  "user.enable": "enabled an account",
  "plugins.repository.add": "added a plugin repository",
  "plugins.repository.remove": "removed a plugin repository",
  "plugins.sync": "synced a plugin repository",
  "robot.register": "registered a robot",
  "robot.update": "changed a robot",
  "robot.remove": "removed a robot",
  "token.create": "created an access token",
  "token.revoke": "revoked an access token",
  "token.use": "used an access token (first use that day)",
};

export const actionWords = (action: string) => ACTION_WORDS[action] ?? action;

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
