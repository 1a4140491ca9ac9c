// When a process started, as Linux tells it in /proc/<pid>/stat: what makes a
// pid name one process rather than whichever program is given the number next.
// The second field is the program's name in parentheses, which may itself hold
// spaces and parentheses, so the fields are counted from the last ")".

/** Field 22 of a /proc/<pid>/stat line (clock ticks after boot), or null when the line is not one. */
export function startTimeOf(stat: string): string | null {
  const end = stat.lastIndexOf(")");
  if (end < 0) return null;
  // What follows the name starts at field 3 (the state), so field 22 is the 20th of them.
  const started = stat
    .slice(end + 1)
    .trim()
    .split(/\s+/)[19];
  return started && /^\d+$/.test(started) ? started : null;
}
