// Checks of an incoming op's fields, worded as rosbridge's type checks are
// (the text goes to the log), and how a service name is found in the graph.

type Message = Record<string, unknown>;

export function requireString(m: Message, field: string): string {
  if (!(field in m)) throw new Error(`missing ${field}`);
  if (typeof m[field] !== "string") throw new Error(`${field} must be a string`);
  return m[field] as string;
}

export function optionalInteger(m: Message, field: string): number {
  if (m[field] === undefined) return 0;
  if (!Number.isInteger(m[field])) throw new Error(`${field} must be an integer`);
  return m[field] as number;
}

/** A service name without its leading slash is the same service. */
export const graphName = (name: string) => (name.startsWith("/") ? name : `/${name}`);
