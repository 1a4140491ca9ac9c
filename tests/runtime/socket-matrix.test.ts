// Every socket message × every role × (a) its own study's ids, (b) another
// study's ids, (c) a mix of both in every id key it could carry. Generated
// from the protocol's own declaration (clientMessageSchema, commandSchema, and
// the `id` schema every id field uses), so a new message or command is covered
// without editing this file; a new kind of id fails here until it is given one.
import { eq, inArray } from "drizzle-orm";
import type { z } from "zod";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { clientMessageSchema, commandSchema, id } from "../../src/core/socket/messages";
import { annotations, codeEvents, trialEvents, trials } from "../../src/store/schema";
import { socketFixture, STUDY_ROLES_HERE, type Person } from "../support/socket-fixture";

type Fixture = Awaited<ReturnType<typeof socketFixture>>;
type Side = "own" | "other";
type Field = z.ZodType & { def: { type: string; innerType?: Field; values?: unknown[] } };

/** For one case: the id of each kind, in study A (own) and study B (other). */
interface Ids {
  trialId: string;
  studyId: string;
  recordingId: string;
  /** Live video: a connection of that study's trial, by its peer id. */
  peerId: string;
  schemeVersionId: string;
}
const ID_KEYS: Record<string, (side: Side, ids: Record<Side, Ids>) => string> = {
  actionId: (side) => `${side === "own" ? "A" : "B"}-ask`,
  optionId: (side) => `${side === "own" ? "A" : "B"}-yes`,
  stepId: (side) => `${side === "own" ? "A" : "B"}-step-2`,
  recordingId: (side, ids) => ids[side].recordingId,
  trialId: (side, ids) => ids[side].trialId,
  studyId: (side, ids) => ids[side].studyId,
  peerId: (side, ids) => ids[side].peerId,
  schemeVersionId: (side, ids) => ids[side].schemeVersionId,
};

/** Fields that are neither ids nor plain values: one valid sample each. */
const SAMPLES: Record<string, unknown> = {
  signal: { kind: "description", description: { type: "offer", sdp: "v=0 Matrix text" } },
};

/** A message's template: each field a fixed value, or an id key to fill per variant. */
type Template = { name: string; fields: Record<string, unknown>; idKeys: string[]; command?: Template };

function templateOf(schema: z.ZodObject, name: string): Template {
  const fields: Record<string, unknown> = {};
  const idKeys: string[] = [];
  let command: Template | undefined;
  for (const [key, raw] of Object.entries(schema.shape)) {
    let field = raw as Field;
    while (field.def.type === "optional" || field.def.type === "default") field = field.def.innerType!;
    if (key in SAMPLES) fields[key] = SAMPLES[key];
    else if (field === (id as unknown)) {
      if (key === "requestId") fields[key] = "";
      else if (ID_KEYS[key]) idKeys.push(key);
      else throw new Error(`The socket protocol declares an id "${key}" the matrix has no ids for: add it to ID_KEYS.`);
    } else if (field.def.type === "literal") fields[key] = field.def.values![0];
    else if (field.def.type === "string") fields[key] = "Matrix text";
    else if (field.def.type === "number") fields[key] = 0;
    else if (field.def.type === "boolean") fields[key] = false;
    else if (field.def.type === "record") fields[key] = {};
    else if (field.def.type === "array") fields[key] = [];
    else if (key === "command") command = { name: "", fields: {}, idKeys: [] };
    else
      throw new Error(
        `The matrix cannot fill ${name}.${key} (${field.def.type}): teach templateOf this kind of field.`,
      );
  }
  return { name, fields, idKeys, command };
}

const TEMPLATES: Template[] = clientMessageSchema.options.flatMap((message) => {
  const outer = templateOf(message as unknown as z.ZodObject, String(message.shape.type.value));
  if (!outer.command) return [outer];
  return commandSchema.options.map((c) => ({
    ...outer,
    name: `command ${String(c.shape.kind.value)}`,
    command: templateOf(c as unknown as z.ZodObject, String(c.shape.kind.value)),
  }));
});

/** (a) all own; (b) all other; (c) every proper mix of declared keys, and own keys plus the other study's ids in every key not declared. */
function variantsOf(t: Template): Array<{ name: string; sides: Record<string, Side>; extras: boolean }> {
  const keys = [...t.idKeys, ...(t.command?.idKeys ?? [])];
  const all = (side: Side) => Object.fromEntries(keys.map((k) => [k, side]));
  const variants = [{ name: "own ids", sides: all("own"), extras: false }];
  if (keys.length) variants.push({ name: "other study's ids", sides: all("other"), extras: false });
  for (let mask = 1; mask < 2 ** keys.length - 1; mask++) {
    variants.push({
      name: `mixed ids (${keys.map((k, i) => `${k}: ${mask & (1 << i) ? "other" : "own"}`).join(", ")})`,
      sides: Object.fromEntries(keys.map((k, i) => [k, mask & (1 << i) ? "other" : "own"])),
      extras: false,
    });
  }
  variants.push({ name: "own ids, other study's ids in every undeclared id key", sides: all("own"), extras: true });
  return variants;
}

function build(t: Template, sides: Record<string, Side>, extras: boolean, ids: Record<Side, Ids>) {
  const fill = (part: Template) => {
    const out: Record<string, unknown> = { ...part.fields };
    if ("requestId" in out) out.requestId = crypto.randomUUID();
    for (const key of part.idKeys) out[key] = ID_KEYS[key]!(sides[key]!, ids);
    if (extras) for (const key of Object.keys(ID_KEYS)) if (!(key in out)) out[key] = ID_KEYS[key]!("other", ids);
    return out;
  };
  const message = fill(t);
  if (t.command) message.command = fill(t.command);
  return message;
}

const PEOPLE: Person[] = [...STUDY_ROLES_HERE, "outsider"];
const CASES = PEOPLE.flatMap((who) => TEMPLATES.flatMap((t) => variantsOf(t).map((v) => ({ who, t, v }))));

describe.sequential("every socket message × every role × own, other and mixed study ids", () => {
  let f: Fixture;
  let bTrial = "";
  let bRecording = "";
  let bPeer = "";
  let bWatcher: Awaited<ReturnType<Fixture["open"]>>;
  const aTrials: string[] = [];
  const secretsOfB: string[] = [];
  beforeAll(async () => {
    f = await socketFixture();
    bTrial = await f.b.trial(f.b.people.wizard!, "live");
    bRecording = await f.recording(bTrial);
    // Study B's wizard, connected to B's trial: no signal sent from study A may ever reach it.
    bWatcher = await f.open({ userId: f.b.people.wizard! }, bTrial);
    bPeer = String(bWatcher.messages.find((m) => m.type === "welcome")!.peerId);
    secretsOfB.push(
      f.b.studyId,
      bTrial,
      bRecording,
      f.b.schemeVersionId,
      ...Object.values(f.b.people),
      "B-step-1",
      "B-step-2",
      "B-ask",
      "B-yes",
      "B-smile",
      "B-wave",
      "B experiment",
      "B owner",
      "B wizard",
      bPeer,
    );
  });
  afterAll(async () => f?.stop());

  it("covers every message and command the protocol declares", () => {
    expect(TEMPLATES.map((t) => t.name)).toEqual(
      expect.arrayContaining([
        "hello",
        "ping",
        "annotate",
        "code",
        "replay",
        "replay_stop",
        "signal",
        "camera",
        ...commandSchema.options.map((c) => `command ${String(c.shape.kind.value)}`),
      ]),
    );
  });

  it.each(CASES.map((c) => [c.who, c.t.name, c.v.name, c] as const))(
    "%s · %s · %s",
    async (who, _message, _variant, { t, v }) => {
      const trialId = await f.a.trial(f.a.people.wizard!, "live");
      aTrials.push(trialId);
      const keys = [...t.idKeys, ...(t.command?.idKeys ?? [])];
      const usesRecording = keys.includes("recordingId");
      // The trial's wizard in another tab: the own side's live video peer.
      const peer = keys.includes("peerId") ? await f.open("wizard", trialId) : null;
      const ids: Record<Side, Ids> = {
        own: {
          trialId,
          studyId: f.a.studyId,
          recordingId: usesRecording ? await f.recording(trialId) : "",
          peerId: String(peer?.messages.find((m) => m.type === "welcome")?.peerId ?? ""),
          schemeVersionId: f.a.schemeVersionId,
        },
        other: {
          trialId: bTrial,
          studyId: f.b.studyId,
          recordingId: bRecording,
          peerId: bPeer,
          schemeVersionId: f.b.schemeVersionId,
        },
      };
      const socket = await f.open(who, trialId);
      if (who === "outsider") {
        expect(socket.closed).toEqual({ code: 4403, reason: "You are no longer a member of this study." });
        expect(socket.messages).toEqual([]);
        return;
      }
      const message = build(t, v.sides, v.extras, ids);
      const before = socket.messages.length;
      socket.send(message);
      const reply = await socket.next(
        (m) => socket.messages.indexOf(m) >= before && ["ack", "rejected", "pong"].includes(String(m.type)),
      );
      if (typeof message.requestId === "string") expect(reply.requestId).toBe(message.requestId);
      // (b), (c): an id of another study in any declared key is refused.
      if (Object.values(v.sides).includes("other")) expect(reply).toMatchObject({ type: "rejected" });
      // Roles: observers never command; a wizard commands another wizard's trial only to stop it.
      const kind = t.command ? String(t.command.fields.kind) : null;
      if (kind && (who === "observer" || (who === "otherWizard" && kind !== "emergency_stop")))
        expect(reply).toMatchObject({ type: "rejected" });
      // Live video between the trial's own connections is passed on, from this very connection.
      if (t.name === "signal" && !Object.values(v.sides).includes("other")) {
        expect(reply).toMatchObject({ type: "ack" });
        const welcome = socket.messages.find((m) => m.type === "welcome")!;
        await peer!.next((m) => m.type === "signal" && m.peerId === welcome.peerId);
      }
      if (t.name === "hello")
        expect(reply).toMatchObject({ type: "rejected", reason: expect.stringMatching(/already said hello/) });
      // No read: nothing this socket received, except the refusal of what it sent, names study B.
      await socket.command("after", { kind: "note", text: "drain" }).catch(() => null);
      const received = socket.messages.filter((m) => m.type !== "rejected").map((m) => JSON.stringify(m));
      expect(secretsOfB.filter((s) => received.some((text) => text.includes(s)))).toEqual([]);
      for (const m of socket.messages)
        if (m.type === "events" || m.type === "welcome")
          expect((m.events as Array<{ trialId: string }>).every((e) => e.trialId === trialId)).toBe(true);
      socket.close();
      peer?.close();
    },
  );

  it("passes live video between two trials of one study never, either way", async () => {
    const trialId = await f.a.trial(f.a.people.wizard!, "live");
    const otherTrialId = await f.a.trial(f.a.people.wizard!, "live");
    aTrials.push(trialId, otherTrialId);
    const wizard = await f.open("wizard", trialId);
    const elsewhere = await f.open("observer", otherTrialId);
    const peerOf = (s: typeof wizard) => String(s.messages.find((m) => m.type === "welcome")!.peerId);
    for (const [from, to] of [
      [wizard, elsewhere],
      [elsewhere, wizard],
    ] as const) {
      const requestId = crypto.randomUUID();
      from.send({ type: "signal", requestId, peerId: peerOf(to), signal: SAMPLES.signal });
      expect(await from.next((m) => m.requestId === requestId)).toMatchObject({
        type: "rejected",
        reason: expect.stringMatching(/no longer connected to this trial/),
      });
    }
    await wizard.command("drain", { kind: "note", text: "drain" });
    expect([...wizard.messages, ...elsewhere.messages].filter((m) => m.type === "signal")).toEqual([]);
    wizard.close();
    elsewhere.close();
  });

  it("wrote nothing to the other study, and nothing of it into this study's logs", async () => {
    // Study B's connection was signalled by nobody of study A.
    expect(bWatcher.messages.filter((m) => m.type === "signal")).toEqual([]);
    const bEvents = await f.db.select().from(trialEvents).where(eq(trialEvents.trialId, bTrial));
    expect(bEvents.map((e) => e.type)).toEqual(["trial.started", "step.entered"]);
    expect(await f.db.select().from(annotations).where(eq(annotations.trialId, bTrial))).toEqual([]);
    expect(await f.db.select().from(codeEvents).where(eq(codeEvents.trialId, bTrial))).toEqual([]);
    expect(
      await f.db.select().from(codeEvents).where(eq(codeEvents.versionId, f.b.schemeVersionId)),
      "no code of study A's trials points at study B's scheme",
    ).toEqual([]);
    expect((await f.db.select({ w: trials.wizardId }).from(trials).where(eq(trials.id, bTrial)))[0]!.w).toBe(
      f.b.people.wizard,
    );
    const aLogs = JSON.stringify(await f.db.select().from(trialEvents).where(inArray(trialEvents.trialId, aTrials)));
    const aNotes = JSON.stringify(await f.db.select().from(annotations).where(inArray(annotations.trialId, aTrials)));
    expect(secretsOfB.filter((s) => aLogs.includes(s) || aNotes.includes(s))).toEqual([]);
    expect(aLogs).toContain("Matrix text");
  });
});
