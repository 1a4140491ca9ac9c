// What a settings form changed: the form hands back all of an action's values
// with one edited, and each edit is its own command (its own undo step, typed
// keys merged), so only what differs from the action as it stands is set.

/** The parameters whose value in `after` differs from `before`, as [name, new value]. */
export function changedParameters(
  before: Record<string, unknown>,
  after: Record<string, unknown>,
): Array<[string, unknown]> {
  return Object.entries(after).filter(([name, value]) => value !== before[name]);
}
