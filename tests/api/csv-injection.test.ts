// Every CSV export neutralises text a spreadsheet would run as a formula
// (a cell starting with = + - @, tab or CR gets a leading '), while numbers
// stay numbers: checked through the real export procedures and the study
// archive, with answers, codes, names, notes and speech text a participant
// or researcher could type.
import { strFromU8 } from "fflate";
import { afterAll, describe, expect, it } from "vitest";
import { appendEvents } from "../../src/store/event-store";
import { parseCsv } from "../support/csv";
import { freshDatabase } from "../support/db";
import { buildFixture, unzipArchive } from "./fixture";

const { db, close } = await freshDatabase();
const f = await buildFixture(db);
const owner = f.api("owner");
const participant = f.api("anonymous").form;
afterAll(close);

const HYPERLINK = '=HYPERLINK("http://x","y")';

/** No cell of the CSV could run as a formula. */
const inert = (csv: string) =>
  parseCsv(csv)
    .flat()
    .filter((cell) => /^[=+\-@\t\r]/.test(cell));

async function studyWithAnswers() {
  const study = await f.newStudy();
  const q = await owner.questionnaires.create({ studyId: study.id, name: "@Mood" });
  const draft = (await owner.questionnaires.get({ questionnaireId: q.id })).draft;
  const items = [
    { id: "link", kind: "short_text", text: "+Your favourite website", required: false },
    { id: "scale", kind: "number", text: "-How far (-5 to 5)", required: false },
    { id: "typed", kind: "short_text", text: "What you typed", required: false },
  ];
  await owner.questionnaires.save({
    questionnaireId: q.id,
    definition: { ...draft, title: "@Mood", sections: [{ ...draft.sections[0]!, items }] },
  });
  await owner.questionnaires.publish({ questionnaireId: q.id });
  const p = await owner.participants.create({
    studyId: study.id,
    code: "-P1",
    consentStatus: "given",
    consentDate: new Date(),
  });
  const { token } = await owner.questionnaires.createLink({ questionnaireId: q.id, participantId: p.id });
  await participant.submit({ token, answers: { link: HYPERLINK, scale: -3, typed: "-3" } });
  return { study, p };
}

describe("the questionnaire answers CSV", () => {
  it("writes a formula answer, a code, a title and an item as text, and a number answer as a number", async () => {
    const { study } = await studyWithAnswers();
    const csv = (await owner.questionnaires.exportCsv({ studyId: study.id })).body;
    const rows = parseCsv(csv);
    const row = (item: string) => rows.find((r) => r[7] === item)!;
    expect(row("link")).toEqual([
      "'-P1",
      "",
      "",
      "'@Mood",
      "",
      "1",
      "answer",
      "link",
      "'+Your favourite website",
      "",
      "",
      `'${HYPERLINK}`,
    ]);
    expect(row("scale").slice(8)).toEqual(["'-How far (-5 to 5)", "", "", "-3"]);
    expect(row("typed")[11]).toBe("'-3");
    expect(inert(csv)).toEqual(["-3"]);
  });
});

describe("the trial events CSV", () => {
  it("keeps a note, a step's name and speech text from running, in the trial's download and the study archive", async () => {
    const { study, p } = await studyWithAnswers();
    const e = await owner.experiments.create({ studyId: study.id, name: "E", robotId: "nao6-ros2" });
    await owner.experiments.saveDesign({
      experimentId: e.id,
      baseRevision: 0,
      steps: [{ name: "+Intro", actions: [{ type: "say", parameters: { text: "@everyone hello" } }] }],
    });
    const trial = await owner.trials.create({
      versionId: (await owner.versions.publish({ experimentId: e.id })).id,
      participantId: p.id,
    });
    await appendEvents(
      db,
      { id: trial.id, lastSeq: 0, t0: null },
      [
        { type: "trial.started" },
        { type: "step.entered", stepId: "=cmd|' /C calc'!A0", via: "start" },
        {
          type: "action.requested",
          stepId: null,
          actionId: "a1",
          actionType: "@say",
          parameters: { text: "+1 for robots" },
          scripted: false,
          deviation: "unscripted",
        },
        { type: "note.added", text: '=HYPERLINK("http://x")' },
      ],
      f.people.owner.id,
    );
    const csv = await new Response((await owner.trials.export({ trialId: trial.id, format: "csv" })).body).text();
    expect(inert(csv)).toEqual([]);
    const [header, ...rows] = parseCsv(csv);
    // Cells by column name: the columns grow as the exports learn more.
    const cell = (type: string, column: string) =>
      rows.find((r) => r[header!.indexOf("type")] === type)![header!.indexOf(column)];
    expect(cell("step.entered", "step_id")).toBe("'=cmd|' /C calc'!A0");
    expect(cell("action.requested", "action_type")).toBe("'@say");
    // Speech text, notes and names sit inside the payload's JSON, a cell that starts with "{".
    expect(cell("note.added", "payload")).toMatch(/^\{.*HYPERLINK/);

    const archive = await unzipArchive(await f.routeApi("owner").studies.exportArchive({ studyId: study.id }));
    const files = Object.entries(archive).filter(([name]) => name.endsWith(".csv"));
    expect(files.map(([name]) => name).sort()).toEqual([
      "codebook.csv",
      "codes.csv",
      "questionnaire-answers.csv",
      `trials/${trial.id}-events.csv`,
      `trials/${trial.id}-samples.csv`,
    ]);
    expect(inert(strFromU8(archive[`trials/${trial.id}-events.csv`]!))).toEqual([]);
    expect(inert(strFromU8(archive["questionnaire-answers.csv"]!))).toEqual(["-3"]);
    expect(inert(strFromU8(archive["codebook.csv"]!))).toEqual([]);
  });
});
