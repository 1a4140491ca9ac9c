// Which waiting action a done message answers: the oldest it matches, an
// action sent since a lost link before one whose outcome is unknown, whether
// it is found by the value it expects or tried in turn; a message that
// matches none answers none, however many wait.
import { describe, expect, it } from "vitest";
import type { DoneMatch } from "../../core/plugins";
import { DoneTopics, type DoneAnswer } from "./done-topics";

/** A done topic fed by hand, and each wait's answer once it has one. */
function topic() {
  let publish: (message: unknown) => void = () => {};
  const done = new DoneTopics((_topic, _type, onMessage) => {
    publish = onMessage;
    return () => {};
  });
  const answers = new Map<string, DoneAnswer>();
  const wait = (name: string, match: DoneMatch | undefined, outlivesLoss = false) => {
    const waiting = done.wait("/speech_done", "std_msgs/msg/String", match, Date.now() + 60_000, outlivesLoss);
    void waiting.answer.then((answer) => answers.set(name, answer));
    return waiting;
  };
  const say = async (data: unknown) => {
    publish({ data });
    await new Promise((r) => setImmediate(r));
  };
  const answered = () => [...answers.keys()];
  return { done, wait, say, answered, answers };
}

const said = (text: string): DoneMatch => ({ field: "data", equals: `said: ${text}` });
const anySaid: DoneMatch = { field: "data", startsWith: "said: " };

describe("a done message answers the oldest action it matches", () => {
  const cases: Array<{
    name: string;
    waits: Array<[string, DoneMatch | undefined, boolean?]>;
    messages: unknown[];
    answered: string[];
  }> = [
    {
      name: "the same line twice: the first asked is the first answered",
      waits: [
        ["first", said("hello")],
        ["second", said("hello")],
        ["other", said("bye")],
      ],
      messages: ["said: hello"],
      answered: ["first"],
    },
    {
      name: "a message that matches nothing waiting answers nothing",
      waits: [
        ["a", said("one")],
        ["b", anySaid],
      ],
      messages: ["done: wave"],
      answered: [],
    },
    {
      name: "one found by its value and one tried in turn: the older of the two (tried in turn)",
      waits: [
        ["prefix", anySaid],
        ["exact", said("hi")],
      ],
      messages: ["said: hi"],
      answered: ["prefix"],
    },
    {
      name: "one found by its value and one tried in turn: the older of the two (found by its value)",
      waits: [
        ["exact", said("hi")],
        ["prefix", anySaid],
      ],
      messages: ["said: hi", "said: hi"],
      answered: ["exact", "prefix"],
    },
    {
      name: "an action sent since a lost link before an older one whose outcome is unknown",
      waits: [
        ["unknown", said("hi"), true],
        ["since", said("hi")],
      ],
      messages: ["said: hi", "said: hi"],
      answered: ["since", "unknown"],
    },
    {
      name: "a value that is not a string is matched by its JSON",
      waits: [
        ["number", { field: "data", equals: 3 }],
        ["text", { field: "data", equals: "3" }],
        ["object", { field: "data", equals: { a: [1, 2] } }],
      ],
      messages: ["3", { a: [1, 2] }, 3],
      answered: ["text", "object", "number"],
    },
    {
      name: "no match at all: the first message answers it",
      waits: [["any", undefined]],
      messages: ["anything"],
      answered: ["any"],
    },
  ];
  for (const c of cases)
    it(c.name, async () => {
      const t = topic();
      for (const [name, match, outlives] of c.waits) t.wait(name, match, outlives);
      for (const message of c.messages) await t.say(message);
      expect(t.answered()).toEqual(c.answered);
    });

  it("many lines waiting and many messages answering none: each line still answered in order", async () => {
    const t = topic();
    const lines = Array.from({ length: 2000 }, (_, i) => `line ${i}`);
    for (const line of lines) t.wait(line, said(line));
    // A trial's lines still being said when the next trial took the robot: heard by this one, answering none.
    for (let i = 0; i < 2000; i++) await t.say(`said: earlier trial ${i}`);
    expect(t.answered()).toEqual([]);
    for (const line of lines) await t.say(`said: ${line}`);
    expect(t.answered()).toEqual(lines);
    expect([...t.answers.values()].every((a) => typeof a === "object" && "message" in a)).toBe(true);
  });

  it("a wait cancelled or lost is no longer answered, and the rest still are", async () => {
    const t = topic();
    const cancelled = t.wait("cancelled", said("hi"));
    t.wait("unknown", said("bye"), true);
    t.wait("lost", said("bye"));
    cancelled.cancel();
    t.done.lose();
    // Sent once the link is back.
    t.wait("kept", said("hi"));
    await t.say("said: hi");
    await t.say("said: bye");
    expect(t.answers.get("cancelled")).toBe("lost");
    expect(t.answers.get("lost")).toBe("lost");
    expect(t.answers.get("kept")).toEqual({ message: { data: "said: hi" } });
    expect(t.answers.get("unknown")).toEqual({ message: { data: "said: bye" } });
  });
});
