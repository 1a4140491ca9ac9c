import { spawnSync } from "node:child_process";
import { describe, expect, it } from "vitest";
import { shellCommand, shellWords } from "./shell";

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
    expect(shellWords(built.command)).toEqual({ ok: true, words: argv });
  });

  it.each<[string, Record<string, unknown>, string]>([
    ["qicli call ALTextToSpeech.say {{text}}", {}, '/3: no value for parameter "text"'],
    ["qicli call ALTextToSpeech.say {{text}}", { text: "a\0b" }, "argument 4 contains a NUL character"],
    ["   ", {}, "the command template is empty"],
  ])("refuses %j with %j", (template, parameters, reason) => {
    expect(shellCommand(template, parameters)).toEqual({ ok: false, reason });
  });
});

describe("reading a command back into its arguments, as sh would", () => {
  it.each<[string, string[]]>([
    ["qicli call ALMotion.wakeUp", ["qicli", "call", "ALMotion.wakeUp"]],
    ["  qicli   call\tALMotion.rest  ", ["qicli", "call", "ALMotion.rest"]],
    [
      "'qicli' 'call' 'ALRobotPosture.goToPosture' 'Sit' '0.5'",
      ["qicli", "call", "ALRobotPosture.goToPosture", "Sit", "0.5"],
    ],
    [`say "it's \\"fine\\"" a\\ b`, ["say", `it's "fine"`, "a b"]],
    ["say 'don'\\''t' ''", ["say", "don't", ""]],
    ['say "two\\\nlines" one\\\ntwo', ["say", "twolines", "onetwo"]],
    ["say a#b x~", ["say", "a#b", "x~"]],
    ["", []],
  ])("%j", (command, argv) => {
    expect(argvAfterShell(command)).toEqual(argv);
    expect(shellWords(command)).toEqual({ ok: true, words: argv });
  });

  it.each<[string, string]>([
    ["qicli call 'x", "a single quote is not closed"],
    ['qicli call "x', "a double quote is not closed"],
    ["qicli call x\\", "the command ends with a backslash"],
    ["qicli call x; reboot", '";" asks the shell for more than one plain command'],
    ["qicli call x && reboot", '"&" asks the shell for more than one plain command'],
    ["qicli call $(reboot)", '"$" asks the shell for more than one plain command'],
    ['qicli call "$HOME"', '"$" asks the shell to substitute'],
    ["qicli call `id`", '"`" asks the shell for more than one plain command'],
    ["qicli call x > /etc/passwd", '">" asks the shell for more than one plain command'],
    ["qicli call *", '"*" asks the shell to expand it'],
    ["qicli call ~/x", '"~" asks the shell to expand it'],
    ["qicli call #x", '"#" asks the shell to expand it'],
  ])("refuses %j: %s", (command, reason) => {
    expect(shellWords(command)).toEqual({ ok: false, reason });
  });
});
