// A study's sounds: uploaded through their route (the bytes decide the type,
// the body limit holds), streamed in byte ranges to whoever may run a trial,
// pinned by published versions (never deleted from under one), and a note
// for the wizard kept with each action through saving and publishing.
import { readFileSync } from "node:fs";
import { afterAll, describe, expect, it } from "vitest";
import { silentWav } from "../support/audio";
import { ORIGIN, routeServer } from "../support/routes";

const s = await routeServer();
afterAll(s.close);
const upload = await import("../../src/app/api/studies/[studyId]/audio/route");
const media = await import("../../src/app/api/audio/[audioFileId]/route");
const owner = await s.signIn("owner");
const wizard = await s.signIn("wizard");
const observer = await s.signIn("observer");
const api = await s.apiAs(owner);
const study = await s.f.newStudy();

const post = (name: string, body: Uint8Array<ArrayBuffer>, who = owner, headers: Record<string, string> = {}) =>
  upload.POST(
    new Request(`${ORIGIN}/api/studies/${study.id}/audio?name=${encodeURIComponent(name)}`, {
      method: "POST",
      headers: { cookie: who.get("cookie")!, "content-type": "audio/wav", ...headers },
      body,
    }),
    { params: Promise.resolve({ studyId: study.id }) },
  );
const get = (audioFileId: string, who: Headers, headers: Record<string, string> = {}) =>
  media.GET(
    new Request(`${ORIGIN}/api/audio/${audioFileId}`, { headers: { cookie: who.get("cookie")!, ...headers } }),
    { params: Promise.resolve({ audioFileId }) },
  );
const added = async (name: string, bytes: Uint8Array<ArrayBuffer>) => {
  const res = await post(name, bytes);
  expect(res.status, await res.clone().text()).toBe(201);
  return (await res.json()) as { id: string; name: string; sha256: string; durationMs: number | null };
};
const playAudio = (file: { id: string; name: string; sha256: string }) => ({
  type: "play_audio",
  parameters: { fileId: file.id, name: file.name, sha256: file.sha256 },
});

async function experimentWith(steps: Parameters<typeof api.experiments.saveDesign>[0]["steps"]) {
  const e = await api.experiments.create({
    studyId: study.id,
    name: `E ${crypto.randomUUID().slice(0, 6)}`,
    robotId: "nao6-ros2",
  });
  await api.experiments.saveDesign({ experimentId: e.id, baseRevision: 0, steps });
  return e;
}

describe("a study's sounds", () => {
  it("takes a WAV, MP3 or Ogg by its bytes, whatever it is called, with its hash and length", async () => {
    const wav = await added("C:\\Users\\lab\\chime.wav", silentWav(500));
    expect(wav).toMatchObject({ name: "chime.wav", durationMs: 500, sha256: expect.stringMatching(/^[0-9a-f]{64}$/) });
    const mp3 = await added("named-wrongly.ogg", new Uint8Array(readFileSync("tests/fixtures/audio/gsutil-test.mp3")));
    expect(mp3).toMatchObject({ durationMs: 1176 });
    const list = await api.audio.list({ studyId: study.id });
    expect(list.map((f) => [f.name, f.mimeType])).toEqual(
      expect.arrayContaining([
        ["chime.wav", "audio/wav"],
        ["named-wrongly.ogg", "audio/mpeg"],
      ]),
    );
  });

  it("refuses a file that is not a sound, plainly, and stores nothing", async () => {
    const before = (await api.audio.list({ studyId: study.id })).length;
    const res = await post("slides.wav", new TextEncoder().encode("%PDF-1.7 not a sound"));
    expect(res.status).toBe(415);
    expect(await res.text()).toBe(
      "“slides.wav” is not a WAV, MP3 or Ogg sound file (judged by its contents, not its name): convert it to one of these and upload it again.",
    );
    expect(await api.audio.list({ studyId: study.id })).toHaveLength(before);
  });

  it("refuses a file over the limit before reading it", async () => {
    const res = await post("long.wav", silentWav(10), owner, { "content-length": String(21 * 1024 * 1024) });
    expect(res.status).toBe(413);
    expect(await res.text()).toBe("A sound file may be at most 20 MB; this one is 21 MB.");
  });

  it("only editors add sounds", async () => {
    const res = await post("w.wav", silentWav(10), wizard);
    expect(res.status).toBe(403);
  });

  it("streams a sound whole or in ranges to whoever may run a trial; an observer may not fetch it", async () => {
    const file = await added("tone.wav", silentWav(100));
    const whole = await get(file.id, wizard);
    expect(whole.status).toBe(200);
    expect(Object.fromEntries(whole.headers)).toMatchObject({
      "content-type": "audio/wav",
      "content-length": String(44 + 1600),
      "accept-ranges": "bytes",
    });
    expect(new Uint8Array(await whole.arrayBuffer())).toEqual(silentWav(100));
    const part = await get(file.id, owner, { range: "bytes=0-3" });
    expect(part.status).toBe(206);
    expect(new TextDecoder().decode(await part.arrayBuffer())).toBe("RIFF");
    expect((await get(file.id, observer)).status).toBe(403);
  });

  it("a published version pins its sound: deleting it is refused, naming the version; an unused one goes", async () => {
    const used = await added("greeting.wav", silentWav(200));
    const unused = await added("spare.wav", silentWav(200));
    const e = await experimentWith([{ name: "Hello", actions: [playAudio(used)] }]);
    const v = await api.versions.publish({ experimentId: e.id });
    expect(v.snapshot.steps[0]!.actions[0]!.parameters).toEqual({
      fileId: used.id,
      name: "greeting.wav",
      sha256: used.sha256,
    });
    await expect(api.audio.remove({ audioFileId: used.id })).rejects.toThrow(
      `“greeting.wav” is played by version 1 of “${e.name}”: a published version must play the same sound every time, so the file stays.`,
    );
    expect((await get(used.id, owner)).status).toBe(200);
    await api.audio.remove({ audioFileId: unused.id });
    expect((await get(unused.id, owner)).status).toBe(404);
    expect(await s.server.media.storage.list(`audio/${study.id}/`)).not.toContainEqual(
      expect.stringContaining(unused.id),
    );
  });

  it("publishing refuses a sound that is not the study's, or not the bytes chosen", async () => {
    const other = await s.f.newStudy();
    const foreign = await (await s.apiAs(owner)).audio.list({ studyId: other.id });
    expect(foreign).toEqual([]);
    const mine = await added("mine.wav", silentWav(50));
    const stranger = await experimentWith([
      { name: "Odd", actions: [playAudio({ id: "not-a-file", name: "x.wav", sha256: mine.sha256 })] },
    ]);
    await expect(api.versions.publish({ experimentId: stranger.id })).rejects.toThrow(
      "This experiment cannot be published: the sound “x.wav” in step “Odd” is not one of this study's sounds: choose it again.",
    );
    const changed = await experimentWith([{ name: "Odd", actions: [playAudio({ ...mine, sha256: "0".repeat(64) })] }]);
    await expect(api.versions.publish({ experimentId: changed.id })).rejects.toThrow(
      "the sound “mine.wav” in step “Odd” has changed since it was chosen: choose it again.",
    );
  });
});

describe("a note for the wizard", () => {
  it("is saved with its action, published in the snapshot, and absent where there is none", async () => {
    const e = await experimentWith([
      {
        name: "Greet",
        description: "Wait until the participant is seated.",
        actions: [
          { type: "say", parameters: { text: "Hello!" }, note: "Say it warmly; wait for eye contact." },
          { type: "wave" },
        ],
      },
    ]);
    const design = await api.experiments.get({ experimentId: e.id });
    expect(design.steps[0]!.actions.map((a) => a.note)).toEqual(["Say it warmly; wait for eye contact.", ""]);
    const v = await api.versions.publish({ experimentId: e.id });
    expect(v.snapshot.steps[0]!.actions[0]!.note).toBe("Say it warmly; wait for eye contact.");
    expect("note" in v.snapshot.steps[0]!.actions[1]!).toBe(false);
    expect(v.snapshot.steps[0]!.description).toBe("Wait until the participant is seated.");
  });

  it("longer than 2000 characters is refused, naming the field", async () => {
    const e = await api.experiments.create({ studyId: study.id, name: "Long note", robotId: "nao6-ros2" });
    await expect(
      api.experiments.saveDesign({
        experimentId: e.id,
        baseRevision: 0,
        steps: [{ name: "S", actions: [{ type: "wave", note: "n".repeat(2001) }] }],
      }),
    ).rejects.toThrow("Note for the wizard must be at most 2000 characters");
  });
});
