import { spawnSync } from "node:child_process";
import { describe, expect, it } from "vitest";
import { shellCommand } from "./shell";

/** What sh actually passes to the program, one argument per line of JSON. */
function argvAfterShell(command: string): string[] {
  const run = spawnSync("sh", ["-c", `set -- ${command}; for a in "$@"; do printf '%s\\0' "$a"; done`], {
    encoding: "utf8",
  });
  return run.stdout.split("\0").slice(0, -1);
}

describe("SSH command templates", () => {
  it.each<[string, Record<string, unknown>, string[]]>([
    ["qicli call ALMotion.wakeUp", {}, ["qicli", "call", "ALMotion.wakeUp"]],
    [
      "qicli call ALRobotPosture.goToPosture {{posture}} {{speed}}",
      { posture: "Stand", speed: 0.5 },
      ["qicli", "call", "ALRobotPosture.goToPosture", "Stand", "0.5"],
    ],
    [
      "qicli call ALTextToSpeech.say {{text}}",
      { text: "'; touch /tmp/pwned; echo '" },
      ["qicli", "call", "ALTextToSpeech.say", "'; touch /tmp/pwned; echo '"],
    ],
    [
      "qicli call ALTextToSpeech.say {{text}}",
      { text: "$(reboot) `id` && | > {{text}} \\ \n line" },
      ["qicli", "call", "ALTextToSpeech.say", "$(reboot) `id` && | > {{text}} \\ \n line"],
    ],
    [
      "qicli call ALTextToSpeech.say {{text}}",
      { text: "Kai sah einen roten Stein 🪨 — 赤い石" },
      ["qicli", "call", "ALTextToSpeech.say", "Kai sah einen roten Stein 🪨 — 赤い石"],
    ],
  ])("%s with %j reaches the program as exactly these arguments", (template, parameters, argv) => {
    const built = shellCommand(template, parameters);
    if (!built.ok) throw new Error(built.reason);
    expect(built.argv).toEqual(argv);
    expect(argvAfterShell(built.command)).toEqual(argv);
  });

  it.each<[string, Record<string, unknown>, string]>([
    ["qicli call ALTextToSpeech.say {{text}}", {}, '/3: no value for parameter "text"'],
    ["qicli call ALTextToSpeech.say {{text}}", { text: "a\0b" }, "argument 4 contains a NUL character"],
    ["   ", {}, "the command template is empty"],
  ])("refuses %j with %j", (template, parameters, reason) => {
    expect(shellCommand(template, parameters)).toEqual({ ok: false, reason });
  });
});
