// A trial as an ELAN annotation document (EAF 3.0), so video coders can open
// the trial's steps, actions, answers, deviations and annotations beside the video
// in the tool they already use. Times are milliseconds from the trial's t0,
// or, when the trial was recorded, from the start of the linked recording.
import type { CodeRowInput } from "../coding/export";
import { blockName, type ActionNames } from "../designer/action-name";
import type { TrialEvent, TrialProtocol } from "../trial";
import { answerOf } from "./answers";
import { fidelityReport } from "./fidelity";
import { trialNames } from "./names";

export interface ElanInput {
  protocol: TrialProtocol;
  events: TrialEvent[];
  annotations: Array<{ relMs: number; label: string; note: string }>;
  /** The trial's recording: the document links it, and its times become the recording's. */
  media?: { fileName: string; mimeType: string; offsetMs: number };
  /** When the trial ran (ISO 8601): the document's date. */
  date: string;
  /** The robot plugin's names of its own actions (see actionNamesOf). */
  names?: ActionNames;
  /** Observers' code events: one tier per observer per set of codes. */
  codes?: CodeRowInput[];
}

type Span = { start: number; end: number; value: string };

const MOMENT_MS = 1000;

const escapeXml = (text: string) =>
  text.replace(/[<>&'"]/g, (c) => ({ "<": "&lt;", ">": "&gt;", "&": "&amp;", "'": "&apos;", '"': "&quot;" })[c]!);

/** ELAN wants every annotation to last: an instant becomes a millisecond. */
const span = (start: number, end: number | null, value: string): Span => ({
  start,
  end: Math.max(start + 1, end ?? start + 1),
  value,
});

/**
 * A coder reads what was said in full: speech and instructions carry their
 * whole text after the label (or the block's name); anything else is its
 * display name.
 */
function spoken(
  action: { type: string; name?: string; parameters: Record<string, unknown> },
  shown: string,
  names?: ActionNames,
) {
  const text = action.parameters.text;
  return typeof text === "string" ? `${action.name?.trim() || blockName(action.type, names)}: ${text}` : shown;
}

function tiers(input: ElanInput): Record<string, Span[]> {
  const report = fidelityReport(input.protocol, input.events, input.names);
  const planned = new Map(input.protocol.steps.flatMap((s) => s.actions.map((a) => [a.id, a])));
  const lastMs = Math.max(0, ...input.events.map((e) => e.relMs ?? 0));
  const steps = report.steps
    .filter((s) => s.enteredMs !== null)
    .map((s) => span(s.enteredMs!, s.leftMs ?? lastMs, s.name));
  const actions = report.actions
    .filter((a) => a.requestedMs !== null)
    .map((a) =>
      span(a.requestedMs!, a.requestedMs! + (a.durationMs ?? 0), spoken(planned.get(a.actionId)!, a.name, input.names)),
    );
  const unscripted = report.unscripted
    .filter((u) => u.requestedMs !== null)
    .map((u) =>
      span(
        u.requestedMs!,
        u.requestedMs! + (u.durationMs ?? 0),
        `${spoken({ type: u.type, parameters: u.parameters }, u.name, input.names)} (unscripted)`,
      ),
    );
  // The answer's value on a tier of its own, at the moment it was recorded; its question is on the Action tier then.
  const answers = input.events.flatMap((e) => {
    const answer = answerOf(e);
    return answer === undefined || e.relMs === null ? [] : [span(e.relMs, null, answer)];
  });
  const named = trialNames(input.protocol, input.events, input.names);
  const deviations = input.events
    .filter((e) => e.deviation && e.relMs !== null)
    .map((e) => {
      const { stepName, actionName } = named.of(e);
      return span(e.relMs!, null, `${e.deviation!.replace("_", " ")}: ${actionName ?? stepName ?? e.type}`);
    });
  const senses = input.events.flatMap((e) =>
    e.type === "robot.sensed" && e.relMs !== null ? [span(e.relMs, null, sensedValue(e))] : [],
  );
  const annotations = input.annotations.map((m) =>
    span(m.relMs, m.relMs + MOMENT_MS, m.note ? `${m.label}: ${m.note}` : m.label),
  );
  return {
    Step: steps,
    Action: [...actions, ...unscripted].sort((a, b) => a.start - b.start),
    Answer: answers,
    Deviation: deviations,
    // Only in a trial whose robot sensed something: earlier trials' files keep their tiers.
    ...(senses.length ? { "Robot senses": senses } : {}),
    Annotation: annotations,
    ...codeTiers(input.codes ?? [], lastMs),
  };
}

/** What the robot sensed, by its own clock, and the message that matched: "head_touched (robot's time …): {…}". */
function sensedValue(e: Extract<TrialEvent, { type: "robot.sensed" }>): string {
  return `${e.event} (robot's time ${new Date(e.at).toISOString()}): ${JSON.stringify(e.message)}`;
}

/**
 * "<observer> - <set>" tiers, as ELAN's own multi-coder files name them: a
 * state spans its start to its end (one still held, to the trial's last
 * event), a point event lasts a millisecond; modifiers follow the code's name.
 */
function codeTiers(codes: CodeRowInput[], lastMs: number): Record<string, Span[]> {
  const tiers: Record<string, Span[]> = {};
  for (const c of codes) {
    const set = c.scheme.sets.find((s) => s.id === c.setId);
    const name = set?.codes.find((x) => x.id === c.codeId)?.name ?? c.codeId;
    const value = c.modifiers.length ? `${name} (${c.modifiers.join(", ")})` : name;
    const end = c.kind === "state" ? (c.endMs ?? Math.max(lastMs, c.startMs + 1)) : null;
    (tiers[`${c.observer} - ${set?.name ?? c.setId}`] ??= []).push(span(c.startMs, end, value));
  }
  return tiers;
}

export function elanDocument(input: ElanInput): string {
  const byTier = tiers(input);
  // With a recording, a time is where it falls in the recording: trial time minus the recording's offset from t0.
  const shift = -(input.media?.offsetMs ?? 0);
  const slots: number[] = [];
  const slot = (ms: number) => {
    slots.push(Math.max(0, ms + shift));
    return `ts${slots.length}`;
  };
  let nextId = 0;
  const tierXml = Object.entries(byTier).map(([name, spans]) => {
    const body = spans
      .map((s) => {
        const [a, b] = [slot(s.start), slot(s.end)];
        return `      <ANNOTATION><ALIGNABLE_ANNOTATION ANNOTATION_ID="a${++nextId}" TIME_SLOT_REF1="${a}" TIME_SLOT_REF2="${b}"><ANNOTATION_VALUE>${escapeXml(s.value)}</ANNOTATION_VALUE></ALIGNABLE_ANNOTATION></ANNOTATION>`;
      })
      .join("\n");
    return `  <TIER TIER_ID="${escapeXml(name)}" LINGUISTIC_TYPE_REF="default-lt">\n${body}\n  </TIER>`;
  });
  const media = input.media
    ? `\n    <MEDIA_DESCRIPTOR MEDIA_URL="file:///${escapeXml(input.media.fileName)}" RELATIVE_MEDIA_URL="./${escapeXml(input.media.fileName)}" MIME_TYPE="${escapeXml(input.media.mimeType.split(";")[0]!)}"/>`
    : "";
  return `<?xml version="1.0" encoding="UTF-8"?>
<ANNOTATION_DOCUMENT AUTHOR="HRIStudio" DATE="${escapeXml(input.date)}" FORMAT="3.0" VERSION="3.0" xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance" xsi:noNamespaceSchemaLocation="http://www.mpi.nl/tools/elan/EAFv3.0.xsd">
  <HEADER MEDIA_FILE="" TIME_UNITS="milliseconds">${media}
  </HEADER>
  <TIME_ORDER>
${slots.map((ms, i) => `    <TIME_SLOT TIME_SLOT_ID="ts${i + 1}" TIME_VALUE="${Math.round(ms)}"/>`).join("\n")}
  </TIME_ORDER>
${tierXml.join("\n")}
  <LINGUISTIC_TYPE LINGUISTIC_TYPE_ID="default-lt" TIME_ALIGNABLE="true" GRAPHIC_REFERENCES="false"/>
</ANNOTATION_DOCUMENT>
`;
}
