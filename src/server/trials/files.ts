// A trial as files: its events as tidy CSV, its full record as JSON (the
// protocol version embedded, events, marked moments, questionnaires), or an
// ELAN document for video coding. The
// trial's download and the study's archive both take them from here.
import { asc, eq } from "drizzle-orm";
import { elanDocument } from "@/core/analysis/elan";
import { eventsCsv, trialRecordJson } from "@/core/analysis/exports";
import type { TrialEvent } from "@/core/trial";
import type { ProtocolSnapshot } from "@/core/protocol/snapshot";
import type { Database } from "../db/client";
import { annotations, experimentVersions, mediaRecordings, questionnaireLinks, trials, user } from "../db/schema";
import { recordingFileName } from "../media/recordings";
import { submitted } from "../questionnaires/responses";
import { eventsSince } from "./event-store";

export async function trialFile(db: Database, trialId: string, format: "csv" | "json" | "eaf") {
  const [trial] = await db.select().from(trials).where(eq(trials.id, trialId));
  const events = await eventsSince(db, trialId);
  const name = `trial-${trialId}`;
  if (format === "csv") return { filename: `${name}-events.csv`, contentType: "text/csv; charset=utf-8", body: eventsCsv(trialId, events) };
  const [version] = trial!.versionId ? await db.select().from(experimentVersions).where(eq(experimentVersions.id, trial!.versionId)) : [];
  const marked = await db
    .select({ relMs: annotations.relMs, label: annotations.label, note: annotations.note, authorName: user.name })
    .from(annotations)
    .leftJoin(user, eq(user.id, annotations.authorId))
    .where(eq(annotations.trialId, trialId))
    .orderBy(asc(annotations.relMs));
  const protocol = (version?.snapshot ?? trial!.rehearsalSnapshot) as ProtocolSnapshot;
  const recordings = await db.select().from(mediaRecordings).where(eq(mediaRecordings.trialId, trialId)).orderBy(asc(mediaRecordings.createdAt));
  if (format === "eaf") {
    const video = recordings.find((r) => r.status === "complete" && r.kind === "video");
    const media = video ? { fileName: recordingFileName(video.id, video.mimeType), mimeType: video.mimeType, offsetMs: video.offsetMs ?? 0 } : undefined;
    const body = elanDocument({ protocol, events: events as unknown as TrialEvent[], annotations: marked, date: (trial!.t0 ?? trial!.createdAt).toISOString(), media });
    return { filename: `${name}.eaf`, contentType: "application/xml; charset=utf-8", body };
  }
  const record = trialRecordJson({
    trial: { ...trial, rehearsalSnapshot: undefined, version: version ? { id: version.id, number: version.version, hash: version.hash, pluginId: version.pluginId, pluginVersion: version.pluginVersion } : null },
    protocol,
    events,
    annotations: marked,
    questionnaires: await submitted(db, eq(questionnaireLinks.trialId, trialId)),
    recordings: recordings.map((m) => ({
      id: m.id,
      kind: m.kind,
      mimeType: m.mimeType,
      status: m.status,
      sizeBytes: m.sizeBytes,
      offsetMs: m.offsetMs,
      durationMs: m.durationMs,
      url: `/api/recordings/${m.id}/media`,
    })),
  });
  return { filename: `${name}.json`, contentType: "application/json", body: record };
}
