// The trial runtime's engine settings: given where the environment is silent, never over what it sets.
import { describe, expect, it } from "vitest";
import { runtimeEngine } from "./runtime-engine";

describe("the trial runtime's engine settings", () => {
  it("starts the runtime without JavaScriptCore's top tier, unless the environment says otherwise", () => {
    expect(runtimeEngine({})).toEqual({ BUN_JSC_useFTLJIT: "false" });
    expect(runtimeEngine({ BUN_JSC_useFTLJIT: "true" })).toEqual({});
  });
});
