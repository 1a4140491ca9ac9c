// The trial runtime's engine settings: given where the environment is silent, never over what it sets.
import { describe, expect, it } from "vitest";
import { withRuntimeEngine } from "./runtime-engine";

describe("the trial runtime's engine settings", () => {
  it("starts the runtime without JavaScriptCore's top tier, unless the environment says otherwise", () => {
    expect(withRuntimeEngine({ PORT: "1" })).toEqual({ BUN_JSC_useFTLJIT: "false", PORT: "1" });
    expect(withRuntimeEngine({ BUN_JSC_useFTLJIT: "true" })).toEqual({ BUN_JSC_useFTLJIT: "true" });
  });
});
