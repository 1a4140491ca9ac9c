// The whole study as one zip: its design and settings, every trial's record
// and events, and every questionnaire answer. What a lab archives or shares
// with a paper. Withdrawn participants' data is left out.
import { strToU8, zipSync } from "fflate";
import { and, asc, eq, inArray, ne } from "drizzle-orm";
import type { Database } from "@/store/client";
import {
  conditions,
  experimentVersions,
  experiments,
  participants,
  questionnaireLinks,
  sessions,
  studies,
} from "@/store/schema";
import { answersCsv } from "@/core/questionnaires/export";
import { methodsText } from "../experiments/methods";
import { fileSlug } from "../file-slug";
import { submitted } from "../questionnaires/responses";
import { tableCsv } from "@/core/analysis/table";
import { codesTable } from "@/core/coding/export";
import { codeRowsOf } from "../coding/rows";
import { trialFiles } from "../trials/files";
import { analysedTrials } from "../analysis/tables";

const README = `HRIStudio study archive

study.json                  the study, its settings (assignment seed included), conditions,
                            participants (codes, consent, demographics, assignment),
                            experiments with every published version, and sessions
experiments/<name>-v<N>-methods.md
                            each published version described for a paper's methods section:
                            robot and plugin version, steps, exact speech, branches, pauses,
                            questionnaires, conditions and assignment, the version's hash
trials/<id>.json            each trial's full record: protocol version, events,
                            annotations, questionnaires, codes
trials/<id>-events.csv      each trial's events, one row per event (RFC 4180)
trials/<id>.eaf             each trial as an ELAN document: steps, actions, deviations, annotations,
                            and one tier per observer per set of codes
codes.csv                   every observer's codes: one row per code event (observer, scheme,
                            set, code, start and end in ms from the trial's start, modifiers)
questionnaire-answers.csv   every submitted answer: one row per participant x item, then scores

Rehearsals are not included. Participants who withdrew are left out, as are their trials
and answers; study.json says how many.
`;

export async function studyArchive(db: Database, studyId: string) {
  const [study] = await db.select().from(studies).where(eq(studies.id, studyId));
  const people = await db
    .select()
    .from(participants)
    .where(eq(participants.studyId, studyId))
    .orderBy(asc(participants.code));
  const kept = people.filter((p) => p.consentStatus !== "withdrawn");
  const conditionRows = await db
    .select()
    .from(conditions)
    .where(eq(conditions.studyId, studyId))
    .orderBy(asc(conditions.name));
  const experimentRows = await db
    .select()
    .from(experiments)
    .where(eq(experiments.studyId, studyId))
    .orderBy(asc(experiments.name));
  const versions = experimentRows.length
    ? await db
        .select()
        .from(experimentVersions)
        .where(
          inArray(
            experimentVersions.experimentId,
            experimentRows.map((e) => e.id),
          ),
        )
        .orderBy(asc(experimentVersions.version))
    : [];
  const trialRows = await analysedTrials(db, studyId);
  const conditionName = (id: string | null) => conditionRows.find((c) => c.id === id)?.name ?? null;
  const files: Record<string, Uint8Array> = {
    "README.txt": strToU8(README),
    "study.json": strToU8(
      JSON.stringify(
        {
          study: {
            id: study!.id,
            title: study!.title,
            description: study!.description,
            status: study!.status,
            settings: study!.settings,
          },
          conditions: conditionRows.map((c) => ({
            name: c.name,
            description: c.description,
            experiment: experimentRows.find((e) => e.id === c.experimentId)?.name,
          })),
          participants: kept.map((p) => ({
            code: p.code,
            consent: { status: p.consentStatus, date: p.consentDate, documentVersion: p.consentVersion },
            demographics: p.demographics,
            condition: conditionName(p.conditionId),
            conditionOrder: Array.isArray(p.conditionOrder) ? (p.conditionOrder as string[]).map(conditionName) : null,
            assignment: p.assignment,
          })),
          withdrawnParticipants: people.length - kept.length,
          experiments: experimentRows.map((e) => ({
            name: e.name,
            robot: e.robotId,
            versions: versions
              .filter((v) => v.experimentId === e.id)
              .map((v) => ({
                version: v.version,
                hash: v.hash,
                pluginVersion: v.pluginVersion,
                publishedAt: v.publishedAt,
                protocol: v.snapshot,
              })),
          })),
          sessions: await db
            .select({
              plannedAt: sessions.plannedAt,
              participant: participants.code,
              condition: conditions.name,
              trialId: sessions.trialId,
            })
            .from(sessions)
            .innerJoin(participants, eq(participants.id, sessions.participantId))
            .innerJoin(conditions, eq(conditions.id, sessions.conditionId))
            .where(and(eq(sessions.studyId, studyId), ne(participants.consentStatus, "withdrawn")))
            .orderBy(asc(sessions.plannedAt)),
        },
        null,
        2,
      ),
    ),
    "questionnaire-answers.csv": strToU8(answersCsv(await submitted(db, eq(questionnaireLinks.studyId, studyId)))),
    "codes.csv": strToU8(
      tableCsv(
        codesTable(
          await codeRowsOf(
            db,
            trialRows.map((t) => t.id),
          ),
        ),
      ),
    ),
  };
  for (const version of versions) {
    const methods = await methodsText(db, version, studyId);
    // Two experiments of a study may share a name; their files may not.
    const name = `experiments/${methods.filename}`;
    files[name in files ? name.replace(/-methods\.md$/, `-${version.id.slice(0, 8)}-methods.md`) : name] = strToU8(
      methods.markdown,
    );
  }
  for (const { id } of trialRows) {
    for (const file of await trialFiles(db, id, ["json", "csv", "eaf"]))
      files[`trials/${file.filename.replace(/^trial-/, "")}`] = strToU8(file.body);
  }
  return {
    filename: `${fileSlug(study!.title, "study")}.zip`,
    contentType: "application/zip",
    body: zipSync(files, { level: 6 }),
  };
}
