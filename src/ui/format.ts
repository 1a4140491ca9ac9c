// Times shown to people: a duration in seconds with one decimal, or a dash when unknown.
export const seconds = (ms: number | null | undefined) =>
  ms === null || ms === undefined ? "—" : `${(ms / 1000).toFixed(1)} s`;
