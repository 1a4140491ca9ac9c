import Ajv from "ajv";
import { describe, expect, it } from "vitest";
import { validateDesign } from "../designer/validate";
import { plainErrors } from "./ajv-errors";
import { compileParameterSchema, validateParameters } from "./parameters";
import type { ParameterSchema, Plugin } from "./types";

// Ajv's own words, and its paths shown raw: none may reach a researcher.
const SCHEMA_WORDING = [/\bNOT\b/, /must NOT/, /\bshould\b/i, /\/parameters\//, /(^|\s)\/\w+/, /instancePath|keyword/];

const schemaOf = (property: Record<string, unknown>, required: string[] = []): ParameterSchema => ({
  type: "object",
  properties: { value: { title: "Value", ...property } as unknown as ParameterSchema["properties"][string] },
  required,
  additionalProperties: false,
});

// [keyword, the property's schema, the value given, the message a researcher reads]
const KEYWORDS: Array<[string, Record<string, unknown>, unknown, string]> = [
  ["minItems", { type: "array", title: "Answers", minItems: 2 }, ["Yes"], '"Answers" needs at least 2 entries'],
  ["maxItems", { type: "array", title: "Answers", maxItems: 2 }, [1, 2, 3], '"Answers" can have at most 2 entries'],
  ["type", { type: "number", title: "Seconds" }, "three", '"Seconds" must be a number'],
  ["type (integer)", { type: "integer" }, 1.5, '"Value" must be a whole number'],
  ["enum", { type: "string", enum: ["stand", "sit"] }, "fly", '"Value" must be one of: "stand", "sit"'],
  ["minimum", { type: "number", title: "Seconds", minimum: 0 }, -1, '"Seconds" must be at least 0'],
  ["maximum", { type: "number", title: "Seconds", maximum: 3600 }, 4000, '"Seconds" must be at most 3600'],
  ["minLength 1", { type: "string", title: "Text", minLength: 1 }, "", '"Text" must not be empty'],
  ["minLength", { type: "string", minLength: 3 }, "ab", '"Value" must be at least 3 characters long'],
  ["maxLength", { type: "string", maxLength: 5 }, "too long", '"Value" must be at most 5 characters long'],
  ["pattern", { type: "string", pattern: "^[a-z]+$" }, "ABC", '"Value" is not in the expected form'],
  [
    "nested required",
    {
      type: "array",
      title: "Answers",
      items: { type: "object", properties: { label: { type: "string", title: "Answer" } }, required: ["label"] },
    },
    [{}],
    'number 1 in "Answers" needs "Answer"',
  ],
  [
    "nested minLength",
    {
      type: "array",
      title: "Answers",
      items: { type: "object", properties: { label: { type: "string", title: "Answer", minLength: 1 } } },
    },
    [{ label: "Yes" }, { label: "" }],
    '"Answer" (number 2 in "Answers") must not be empty',
  ],
  [
    "nested additionalProperties",
    {
      type: "array",
      title: "Answers",
      items: { type: "object", properties: { label: { type: "string" } }, additionalProperties: false },
    },
    [{ label: "Yes", colour: "red" }],
    'number 1 in "Answers" has a field "colour" that does not belong here',
  ],
];

describe("parameter problems in the researcher's words", () => {
  it.each(KEYWORDS)("%s", (_, property, value, expected) => {
    const messages = validateParameters(schemaOf(property), { value }).map((p) => p.message);
    expect(messages).toEqual([expected]);
    for (const message of messages) for (const wording of SCHEMA_WORDING) expect(message).not.toMatch(wording);
  });

  it.each([
    ["required", schemaOf({ type: "string", title: "Text" }, ["value"]), {}, '"Text" is required'],
    ["additionalProperties", schemaOf({ type: "string" }), { txet: "Hi" }, '"txet" is not a parameter of this action'],
  ])("%s", (_, schema, parameters, expected) => {
    expect(validateParameters(schema, parameters).map((p) => p.message)).toEqual([expected]);
  });

  it("a question with one answer says so in the designer, naming the action", () => {
    const messages = validateDesign(
      {
        name: "Quiz",
        description: "",
        robotId: "none",
        steps: [
          {
            id: "s1",
            name: "Question",
            description: "",
            actions: [
              {
                id: "a1",
                type: "record_answer",
                name: "Favourite planet",
                parameters: { options: [{ id: "o1", label: "Mars" }] },
                parallelGroup: null,
              },
            ],
          },
        ],
      },
      null as Plugin | null,
    ).map((i) => i.message);
    expect(messages).toEqual(['"Favourite planet": "Answers" needs at least 2 entries.']);
  });
});

describe("plugin file errors: a JSON Pointer in its own field, the reason in plain words", () => {
  // "date" known, as a validator with formats would know it.
  const ajv = new Ajv({ allErrors: true, strict: false, formats: { date: /^\d{4}-\d{2}-\d{2}$/ } });
  it.each([
    [{ type: "string", format: "date" }, "yesterday", "must be a date"],
    [{ type: "string", pattern: "^[a-z]+$" }, "ABC", "must match the pattern ^[a-z]+$"],
    [{ type: "array", uniqueItems: true }, ["a.json", "a.json"], "lists the same value twice (numbers 1 and 2)"],
    [{ type: "array", minItems: 1 }, [], "needs at least 1 entry"],
    [{ type: "string", maxLength: 2 }, "abc", "must be at most 2 characters long"],
    [{ type: "object", minProperties: 1 }, {}, "needs at least 1 entry"],
    [{ type: "number", exclusiveMinimum: 0 }, 0, "must be more than 0"],
    [{ type: "number", multipleOf: 5 }, 7, "must be a multiple of 5"],
  ])("%j %j", (schema, value, reason) => {
    const validate = ajv.compile(schema);
    expect(validate(value)).toBe(false);
    const errors = plainErrors(validate.errors);
    expect(errors.map((e) => e.reason)).toEqual([reason]);
    for (const wording of SCHEMA_WORDING) expect(reason).not.toMatch(wording);
  });
});

describe("compiling parameter schemas", () => {
  it("compiles a schema once by its content, however often a plugin is read afresh", () => {
    const read = () => ({ type: "object", properties: { seconds: { type: "number", maximum: 3600 } } });
    expect(compileParameterSchema(read())).toBe(compileParameterSchema(read()));
    expect(compileParameterSchema(read())).not.toBe(compileParameterSchema({ type: "object", properties: {} }));
  });
});
