import { describe, expect, it } from "vitest";
import { databaseUnavailable, NO_ANSWER } from "./client";

const wrapped = (cause: unknown) => Object.assign(new Error("Failed query: select …"), { cause });
const code = (c: string) => Object.assign(new Error(c), { code: c });

describe("databaseUnavailable", () => {
  it.each([
    ["no connection opened in time", code("CONNECT_TIMEOUT"), true],
    ["nothing listening", code("ECONNREFUSED"), true],
    ["a silent connection", code(NO_ANSWER), true],
    ["wrapped by the query builder, then by the sign-in library", wrapped(wrapped(code("CONNECT_TIMEOUT"))), true],
    ["a statement the server refused", Object.assign(new Error("syntax"), { severity: "ERROR", code: "42601" }), false],
    ["a bug of ours", new TypeError("x is undefined"), false],
    ["nothing", null, false],
  ])("%s", (_, error, expected) => {
    expect(databaseUnavailable(error)).toBe(expected);
  });
});
