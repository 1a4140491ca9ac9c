// Why a robot could not be reached, in the words a wizard reads. The errors
// come from Node's and Bun's sockets, DNS, fetch, ws and ssh2, each with its
// own shape (a `code`, an ssh2 `level`, a `cause`); the wizard gets one plain
// clause, never a stack or a system call's name.

interface ErrorLike {
  name?: unknown;
  code?: unknown;
  level?: unknown;
  hostname?: unknown;
  message?: unknown;
  cause?: unknown;
}

const BY_CODE: Record<string, (e: ErrorLike) => string> = {
  ENOTFOUND: (e) =>
    typeof e.hostname === "string" ? `no host named "${e.hostname}" was found` : "no host of that name was found",
  ECONNREFUSED: () => "the connection was refused: nothing answers at that address and port",
  EHOSTUNREACH: () => "that address cannot be reached from this network",
  ETIMEDOUT: () => "the robot did not answer in time",
  ECONNRESET: () => "the robot's side cut the connection",
  ERR_SOCKET_BAD_PORT: () => "the port is not a port number (1–65535)",
  ERR_INVALID_URL: () => "the address is not a URL",
};
// The same faults under other names (getaddrinfo's, Bun's fetch's, ssh2's levels).
const SAME_AS: Record<string, string> = {
  EAI_AGAIN: "ENOTFOUND",
  EAI_NONAME: "ENOTFOUND",
  ConnectionRefused: "ECONNREFUSED",
  ENETUNREACH: "EHOSTUNREACH",
  TimeoutError: "ETIMEDOUT",
  "client-timeout": "ETIMEDOUT",
  EPIPE: "ECONNRESET",
};

/** The first line of what the error says, without its class name, and short. */
function said(error: ErrorLike): string {
  const text = typeof error.message === "string" ? error.message : String(error);
  const line = (text.split("\n")[0] ?? "").replace(/^\w*Error:\s*/, "").trim();
  return (line || "an unknown error").slice(0, 200);
}

/** The plain reason for a failed attempt to reach a robot. */
export function linkProblem(error: unknown): string {
  if (typeof error !== "object" || error === null) return said({ message: String(error) });
  const chain: ErrorLike[] = [];
  for (let e: unknown = error; typeof e === "object" && e !== null && chain.length < 5; e = (e as ErrorLike).cause)
    chain.push(e as ErrorLike);
  for (const e of chain) {
    if (e.level === "client-authentication")
      return "the robot refused the login: check the user name and its key or password";
    for (const key of [e.code, e.level, e.name]) {
      if (typeof key !== "string") continue;
      const plain = BY_CODE[SAME_AS[key] ?? key];
      if (plain) return plain(e);
    }
    if (typeof e.message === "string" && /^Invalid URL/i.test(e.message)) return BY_CODE.ERR_INVALID_URL!(e);
    const refused = typeof e.message === "string" && /^Unexpected server response: (\d+)/.exec(e.message);
    if (refused) return `the robot's side refused the connection (HTTP ${refused[1]})`;
    // ws's opening handshake and ssh2's, under no code at all.
    if (typeof e.message === "string" && /timed out/i.test(e.message)) return BY_CODE.ETIMEDOUT!(e);
  }
  return said(chain.at(-1)!);
}
