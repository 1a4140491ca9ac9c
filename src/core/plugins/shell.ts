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

export type ShellWords = { ok: true; words: string[] } | { ok: false; reason: string };

/**
 * The arguments a POSIX shell would pass for one plain command: what the
 * simulated robot reads from an SSH exec. Quotes and backslashes as sh reads
 * them; anything that would make it more than one command (operators,
 * substitutions, redirections) is refused rather than guessed at.
 */
export function shellWords(command: string): ShellWords {
  const words: string[] = [];
  // null between words; "" is a word of its own ('' on the command line).
  let word: string | null = null;
  for (let i = 0; i < command.length; i++) {
    const c = command[i]!;
    if (c === "'") {
      const end = command.indexOf("'", i + 1);
      if (end < 0) return { ok: false, reason: "a single quote is not closed" };
      word = (word ?? "") + command.slice(i + 1, end);
      i = end;
    } else if (c === '"') {
      let text = "";
      for (i++; i < command.length && command[i] !== '"'; i++) {
        const d = command[i]!;
        if (d === "$" || d === "`") return { ok: false, reason: `"${d}" asks the shell to substitute` };
        if (d === "\\" && command[i + 1] === "\n") i++;
        else if (d === "\\" && '"\\$`'.includes(command[i + 1] ?? "")) text += command[++i];
        else text += d;
      }
      if (i >= command.length) return { ok: false, reason: "a double quote is not closed" };
      word = (word ?? "") + text;
    } else if (c === "\\") {
      if (i + 1 >= command.length) return { ok: false, reason: "the command ends with a backslash" };
      if (command[++i] !== "\n") word = (word ?? "") + command[i];
    } else if (/\s/.test(c)) {
      if (word !== null) words.push(word);
      word = null;
    } else if (";&|<>()$`".includes(c)) {
      return { ok: false, reason: `"${c}" asks the shell for more than one plain command` };
    } else if ("*?[".includes(c) || (word === null && "#~".includes(c))) {
      return { ok: false, reason: `"${c}" asks the shell to expand it` };
    } else word = (word ?? "") + c;
  }
  if (word !== null) words.push(word);
  return { ok: true, words };
}
