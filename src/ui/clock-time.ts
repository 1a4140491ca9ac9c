// A clock time as people read it, always with its zone: exports are in UTC,
// so a time on screen without its zone cannot be matched against them.
export function clockTime(at: Date | string): string {
  return new Date(at).toLocaleTimeString(undefined, { timeZoneName: "short" });
}

// A date and time, with its zone for the same reason.
export function clockDateTime(at: Date | string): string {
  return new Date(at).toLocaleString(undefined, { timeZoneName: "short" });
}
