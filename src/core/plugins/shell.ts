// A NAOqi command for the SSH transport, from the plugin's allow-listed
// template: the template's words are fixed by the plugin file, parameters
// only fill placeholders inside words, and every word is single-quoted for
// POSIX sh. A parameter can add no word, no operator, no substitution.
import { fillTemplate } from "./template";

export type ShellCommand = { ok: true; command: string; argv: string[] } | { ok: false; reason: string };

export function quoteWord(word: string): string {
  return `'${word.replaceAll("'", `'\\''`)}'`;
}

export function shellCommand(template: string, parameters: Record<string, unknown>): ShellCommand {
  const words = template.trim().split(/\s+/).filter(Boolean);
  if (words.length === 0) return { ok: false, reason: "the command template is empty" };
  const filled = fillTemplate(words, parameters);
  if (!filled.ok) return { ok: false, reason: `${filled.path}: ${filled.reason}` };
  const argv = (filled.value as unknown[]).map((w) => (typeof w === "string" ? w : JSON.stringify(w)));
  // A NUL cannot travel in an argument: refuse rather than truncate silently.
  const bad = argv.findIndex((w) => w.includes("\0"));
  if (bad >= 0) return { ok: false, reason: `argument ${bad + 1} contains a NUL character` };
  return { ok: true, argv, command: argv.map(quoteWord).join(" ") };
}
