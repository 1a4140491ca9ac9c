// The order a runtime sends in, as one browser process sees it over real
// sockets (its event loop takes each socket's data in the order it came): the
// wizard's ack before the trial's observers are sent the batch, and a long
// welcome in parts with another trial's command answered between them.
import WebSocket from "ws";
import { eq } from "drizzle-orm";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { insertLog, unscriptedLog } from "../../bench/support";
import { parseServerMessage, SOCKET_MESSAGES_VERSION, type WireEvent } from "../../src/core/socket/messages";
import { WELCOME_PART_BYTES, welcomeJoiner } from "../../src/core/socket/welcome";
import { trials } from "../../src/store/schema";
import type { TrialSocket } from "../support/socket";
import { socketFixture } from "../support/socket-fixture";

type Fixture = Awaited<ReturnType<typeof socketFixture>>;
const OBSERVERS = 50;
const EVENTS = 100_000;

describe.sequential("the order the runtime sends in", () => {
  let f: Fixture;
  const sockets: TrialSocket[] = [];
  beforeAll(async () => {
    f = await socketFixture();
  });
  afterAll(async () => {
    for (const s of sockets) s.close();
    await f?.stop();
  });

  it(`acknowledges the wizard's command before any of ${OBSERVERS} observers is sent its events`, {
    timeout: 120_000,
  }, async () => {
    const trialId = await f.a.trial(f.a.people.wizard!, "live");
    // The observers follow the trial first: sent in the order they came, their copies would all go before the wizard's.
    const order: string[] = [];
    for (let i = 0; i < OBSERVERS; i++) {
      const observer = await f.open("observer", trialId);
      observer.listen((m) => m.type === "events" && order.push(`observer ${i}: ${m.events.map((e) => e.seq)}`));
      sockets.push(observer);
    }
    const wizard = await f.open("wizard", trialId);
    sockets.push(wizard);
    wizard.listen((m) => m.type === "ack" && order.push(`ack: ${m.seqs}`));
    for (let n = 0; n < 5; n++) {
      order.length = 0;
      const ack = await wizard.command(`note-${n}`, { kind: "note", text: `Note ${n}` });
      expect(ack.type).toBe("ack");
      const seqs = String(ack.seqs);
      await expect.poll(() => order.filter((o) => o.endsWith(`: ${seqs}`)).length).toBe(OBSERVERS + 1);
      const batch = order.filter((o) => o.endsWith(`: ${seqs}`));
      expect(batch[0], batch.join("\n")).toBe(`ack: ${seqs}`);
    }
  });

  it("sends a 10 MB welcome in parts, and answers another trial's wizard between them", {
    timeout: 180_000,
  }, async () => {
    const large = await f.a.trial(f.a.people.wizard!, "scheduled");
    const stored = unscriptedLog(large, EVENTS, new Date(Date.now() - 3_600_000), (i) => i * 30);
    await insertLog(f.db, stored);
    await f.db.update(trials).set({ status: "completed" }).where(eq(trials.id, large));
    const other = await f.open({ userId: f.b.people.wizard! }, await f.b.trial(f.b.people.wizard!, "live"));
    sockets.push(other);

    const order: string[] = [];
    other.listen((m) => m.type === "ack" && order.push("ack"));
    const join = welcomeJoiner();
    let welcomed: (events: WireEvent[]) => void;
    const welcome = new Promise<WireEvent[]>((ok) => (welcomed = ok));
    const reader = new WebSocket(f.url);
    await new Promise((ok) => reader.once("open", ok));
    reader.on("message", (data) => {
      const text = String(data);
      const parsed = parseServerMessage(text);
      if (!parsed.ok) throw new Error(parsed.reason);
      const joined = join(parsed.message);
      if (!joined.ok) throw new Error(joined.reason);
      if (parsed.message.type === "welcome.part") {
        expect(Buffer.byteLength(text)).toBeLessThanOrEqual(WELCOME_PART_BYTES);
        order.push("part");
        // A slow reader: it reads on only once the other trial's wizard has been answered.
        if (parsed.message.part === 0) {
          reader.pause();
          void other
            .command("between", { kind: "note", text: "Said while the large trial opens" })
            .then(() => reader.resume());
        }
      }
      if (joined.message?.type === "welcome") {
        order.push("welcome");
        welcomed(joined.message.events);
      }
    });
    reader.send(
      JSON.stringify({
        type: "hello",
        version: SOCKET_MESSAGES_VERSION,
        token: f.token(f.a.people.owner!, large),
        lastSeq: 0,
      }),
    );
    // The whole log as stored, each event in its place: what the trial's opening read (the driver's).
    const events = await welcome;
    reader.close();
    expect(events).toHaveLength(EVENTS);
    expect(events.filter((e, i) => e.seq !== i + 1)).toEqual([]);
    for (const i of [0, 1, 2, 3, 50_000, EVENTS - 1])
      expect(events[i], `event ${i + 1}`).toMatchObject({
        ...JSON.parse(stored[i]!.payload),
        seq: i + 1,
        relMs: i * 30,
        trialId: large,
        serverTime: stored[i]!.server_time,
        actorId: null,
      });
    const parts = order.filter((o) => o === "part").length;
    expect(parts).toBeGreaterThanOrEqual(Math.floor((9 * 1024 * 1024) / WELCOME_PART_BYTES));
    expect(order.indexOf("ack"), `${parts} parts`).toBeGreaterThan(order.indexOf("part"));
    expect(order.indexOf("ack")).toBeLessThan(order.indexOf("welcome"));
  });
});
