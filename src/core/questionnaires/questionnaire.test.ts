import { describe, expect, it } from "vitest";
import { answerProblems, consentGiven, presentedOrder, scoreAnswers, type Answers } from "./answers";
import { blankQuestionnaire, builder } from "./builder";
import { definitionSchema, items, type Definition } from "./definition";
import { instrumentDefinition } from "./instruments";

function ids() {
  let n = 0;
  return () => `q${++n}`;
}

describe("the questionnaire builder", () => {
  const start = () => {
    const newId = ids();
    let d = blankQuestionnaire("After the story", newId);
    const section = d.sections[0]!.id;
    for (const kind of ["likert", "single", "multiple", "short_text", "long_text", "number", "consent"] as const)
      d = builder.addItem(d, section, kind, newId());
    return { d, section, newId };
  };

  it("builds a questionnaire of every item kind that the published schema accepts", () => {
    const { d } = start();
    expect(items(d).map((i) => i.kind)).toEqual([
      "likert",
      "single",
      "multiple",
      "short_text",
      "long_text",
      "number",
      "consent",
    ]);
    expect(definitionSchema.safeParse(d).success).toBe(true);
  });

  it.each<[string, (d: Definition, s: string) => Definition, (d: Definition) => unknown, unknown]>([
    [
      "edit an item's text and make it required",
      (d) => builder.updateItem(d, "q2", { text: "How clear was the story?", required: true }),
      (d) => items(d)[0],
      { text: "How clear was the story?", required: true, kind: "likert" },
    ],
    [
      "never change an item's kind or id by editing",
      (d) => builder.updateItem(d, "q2", { kind: "number", id: "x" } as never),
      (d) => [items(d)[0]!.id, items(d)[0]!.kind],
      ["q2", "likert"],
    ],
    [
      "move an item down and up",
      (d) => builder.moveItem(builder.moveItem(d, "q2", 1), "q2", 1),
      (d) =>
        items(d)
          .slice(0, 3)
          .map((i) => i.id),
      ["q3", "q4", "q2"],
    ],
    ["not move past the ends", (d) => builder.moveItem(d, "q2", -1), (d) => items(d)[0]!.id, "q2"],
    ["remove an item", (d) => builder.removeItem(d, "q3"), (d) => items(d).length, 6],
    [
      "add a randomised section",
      (d) => builder.updateSection(builder.addSection(d, "Recall", "s2"), "s2", { randomize: true }),
      (d) => d.sections[1],
      { id: "s2", title: "Recall", randomize: true, items: [] },
    ],
    ["keep the last section", (d, s) => builder.removeSection(d, s), (d) => d.sections.length, 1],
  ])("can %s", (_name, edit, read, expected) => {
    const { d, section } = start();
    const before = structuredClone(d);
    const after = edit(d, section);
    expect(read(after)).toMatchObject(expected as object);
    expect(d).toEqual(before);
  });

  it("refuses a definition with a repeated item id or an empty choice, saying where", () => {
    const { d } = start();
    const twice = {
      ...d,
      sections: [{ ...d.sections[0]!, items: [...d.sections[0]!.items, d.sections[0]!.items[0]!] }],
    };
    expect(definitionSchema.safeParse(twice).error?.issues[0]).toMatchObject({
      path: ["sections", 0, "items", 7, "id"],
      message: '"q2" is used twice',
    });
    const noOptions = builder.updateItem(d, "q3", { options: ["only"] } as never);
    expect(definitionSchema.safeParse(noOptions).error?.issues[0]).toMatchObject({
      message: "needs at least 2 options",
    });
  });
});

describe("answers", () => {
  const { d } = (() => {
    const newId = ids();
    let d = blankQuestionnaire("Q", newId);
    for (const kind of ["likert", "single", "number", "consent"] as const)
      d = builder.addItem(d, d.sections[0]!.id, kind, newId());
    return { d: builder.updateItem(d, "q2", { required: true }) };
  })();

  it.each<[string, Answers, boolean, string[]]>([
    ["a complete, valid set", { q2: 4, q3: "Option 1", q4: 3, q5: true }, true, []],
    ["a partial draft", { q2: 4 }, false, []],
    [
      "a final set missing a required answer and the consent",
      { q3: "Option 2" },
      true,
      [
        "New question: please answer",
        "I have read the information above and agree to take part in this study.: please agree to take part, or leave the study",
      ],
    ],
    ["a point off the scale", { q2: 9 }, false, ["New question: choose a point from 1 to 5"]],
    ["an option that is not offered", { q3: "Option 9" }, false, ["New question: choose one of the options"]],
    ["an item the questionnaire does not have", { zz: 1 }, false, ["zz: is not an item of this questionnaire"]],
  ])("%s", (_name, answers, final, problems) => {
    expect(answerProblems(d, answers, final)).toEqual(problems);
  });

  it("records consent only when every consent item is agreed to", () => {
    expect(consentGiven(d, { q5: true })).toBe(true);
    expect(consentGiven(d, { q5: false })).toBe(false);
    expect(consentGiven(instrumentDefinition("sus"), {})).toBeNull();
  });

  it("shuffles a randomised section the same way for the same link, and leaves others in place", () => {
    const many = builder.updateSection(
      {
        ...d,
        sections: [
          {
            ...d.sections[0]!,
            items: Array.from({ length: 12 }, (_, i) => ({
              id: `i${i}`,
              kind: "short_text" as const,
              text: `Item ${i}`,
              required: false,
            })),
          },
        ],
      },
      d.sections[0]!.id,
      { randomize: true },
    );
    const a = items(presentedOrder(many, "link-a")).map((i) => i.id);
    expect(items(presentedOrder(many, "link-a")).map((i) => i.id)).toEqual(a);
    expect(items(presentedOrder(many, "link-b")).map((i) => i.id)).not.toEqual(a);
    expect([...a].sort()).toEqual(
      items(many)
        .map((i) => i.id)
        .sort(),
    );
    expect(items(presentedOrder(d, "link-a"))).toEqual(items(d));
  });
});

describe("standard instruments as questionnaires", () => {
  it("scores the SUS from its items: 4,2,3,4,3,1,3,3,3,2 gives 60", () => {
    const sus = instrumentDefinition("sus");
    const answers = Object.fromEntries([4, 2, 3, 4, 3, 1, 3, 3, 3, 2].map((v, i) => [`sus${i + 1}`, v]));
    expect(answerProblems(sus, answers, true)).toEqual([]);
    expect(scoreAnswers(sus, answers)).toEqual({ ok: true, score: 60 });
  });

  it("scores Godspeed's five sub-scales as means", () => {
    const godspeed = instrumentDefinition("godspeed");
    expect(items(godspeed)).toHaveLength(24);
    const answers = Object.fromEntries(items(godspeed).map((item, i) => [item.id, i < 5 ? 5 : 3]));
    expect(scoreAnswers(godspeed, answers)).toMatchObject({
      ok: true,
      subscales: { anthropomorphism: 5, animacy: 3, perceivedSafety: 3 },
    });
    expect(definitionSchema.safeParse(godspeed).success).toBe(true);
  });
});
