import { describe, expect, it } from "vitest";
import { parseJsonText } from "../plugins/json-text";
import { finish } from "../work";
import { parsingFile } from "./file-parse";

/** Long enough to be read in pieces. */
const PAD = "p".repeat(300_000);

describe("reading a large file a piece at a time", () => {
  it.each<[string, string]>([
    ["steps of every kind", `{"pad":"${PAD}","steps":[{"a":1},[2,{"b":[3]}],"s",4,null,{}],"z":true}`],
    ["no steps", `{"pad":"${PAD}","steps":[]}`],
    ["steps first, the rest after", `{"steps":[{"x":"]},[{"}],"pad":"${PAD}"}`],
    ["brackets, commas and quotes inside text", `{"pad":"${PAD}","steps":[{"t":"a,b]c\\"d\\\\"},{"u":"[{,"}]}`],
    ["a nested list named steps, left as it is", `{"pad":"${PAD}","experiment":{"steps":[1,2]},"steps":[3]}`],
    ["steps named twice: the last kept", `{"steps":[1],"pad":"${PAD}","steps":[2,3]}`],
    ["a key written with escapes", `{"pad":"${PAD}","st\\u0065ps":[1],"steps":[2]}`],
    ["steps that are not a list", `{"pad":"${PAD}","steps":{"a":[1,2]}}`],
    ["a list at the root", `[{"pad":"${PAD}"},{"steps":[1]}]`],
    ["space everywhere", ` { "pad" : "${PAD}" , "steps" : [ { "a" : 1 } , 2 ] } `],
  ])("%s: what JSON.parse gives", (_name, text) => {
    expect(finish(parsingFile(text))).toEqual({ ok: true, value: JSON.parse(text) });
  });

  it("parses the steps one by one, handing back after each", () => {
    const work = parsingFile(`{"pad":"${PAD}","steps":[${Array(100).fill('{"a":1}').join(",")}]}`);
    let handedBack = 0;
    for (let next = work.next(); !next.done; next = work.next()) handedBack++;
    expect(handedBack).toBeGreaterThanOrEqual(100);
  });

  it.each<[string, string]>([
    ["a comma before the end of the steps", `{"pad":"${PAD}","steps":[1,]}`],
    ["an empty place between steps", `{"pad":"${PAD}","steps":[1,,2]}`],
    ["a broken step", `{"pad":"${PAD}","steps":[{"a":}]}`],
    ["text after the end", `{"pad":"${PAD}","steps":[1]} x`],
    ["an unclosed list", `{"pad":"${PAD}","steps":[1,2`],
  ])("%s: the problem a whole parse reports", (_name, text) => {
    expect(finish(parsingFile(text))).toEqual(parseJsonText(text));
    expect(finish(parsingFile(text)).ok).toBe(false);
  });
});
