// Replays the client side of a rosbridge transcript against a server, at the
// recorded times, and collects what the server sends back.
import { readFileSync } from "node:fs";
import { WebSocket } from "ws";

export const TRANSCRIPTS = "tests/fixtures/rosbridge-transcripts";

export interface Line {
  dir: "send" | "recv" | "event";
  t_ms: number;
  frame?: unknown;
  invalid_json?: true;
  binary?: true;
  event?: "open" | "close" | "terminate";
  code?: number;
  conn?: number;
}

export interface Got {
  conn: number;
  t: number;
  frame: Record<string, unknown>;
}

export function readTranscript(name: string): Line[] {
  return readFileSync(`${TRANSCRIPTS}/${name}`, "utf8")
    .split("\n")
    .filter(Boolean)
    .map((line) => JSON.parse(line) as Line);
}

const sleepUntil = (start: number, t: number) =>
  new Promise((r) => setTimeout(r, Math.max(0, start + t - performance.now())));

const answered = (frame: unknown) => (frame as { topic?: string } | null)?.topic !== "/joint_states";

export async function replay(lines: Line[], url: string, tailMs = 400): Promise<Got[]> {
  const got: Got[] = [];
  const sockets = new Map<number, WebSocket>();
  const start = performance.now();
  // Before a frame is sent or a connection closed, the answers the real server
  // gave before that moment must have arrived: on a loaded machine they can lag
  // the recorded times, and a reply recorded 1 ms before the next send (05's
  // slow service) would otherwise swap places with that send's reply.
  const settled = async (conn: number, upTo: number) => {
    const expected = lines
      .slice(0, upTo)
      .filter((l) => l.dir === "recv" && (l.conn ?? 1) === conn && answered(l.frame)).length;
    for (
      let waited = 0;
      waited < 3000 && got.filter((g) => g.conn === conn && answered(g.frame)).length < expected;
      waited += 20
    ) {
      await new Promise((r) => setTimeout(r, 20));
    }
  };
  for (const [index, line] of lines.entries()) {
    const conn = line.conn ?? 1;
    if (line.dir === "recv") continue;
    await sleepUntil(start, line.t_ms);
    if (line.event === "terminate" || line.event === "close" || line.dir === "send") await settled(conn, index);
    if (line.event === "open") {
      const socket = new WebSocket(url, { perMessageDeflate: false });
      socket.on("message", (data) =>
        got.push({ conn, t: performance.now() - start, frame: JSON.parse(data.toString()) }),
      );
      await new Promise((resolve, reject) => socket.once("open", resolve).once("error", reject));
      sockets.set(conn, socket);
    } else if (line.event === "terminate") {
      sockets.get(conn)!.terminate();
    } else if (line.event === "close" && line.code === 1000) {
      const socket = sockets.get(conn)!;
      await new Promise((resolve) => {
        socket.once("close", resolve);
        socket.close(1000);
      });
    } else if (line.dir === "send") {
      const socket = sockets.get(conn)!;
      if (line.binary) socket.send(Buffer.from(line.frame as string, "base64"), { binary: true });
      else socket.send(line.invalid_json ? (line.frame as string) : JSON.stringify(line.frame));
    }
  }
  await new Promise((r) => setTimeout(r, tailMs));
  sockets.forEach((s) => s.terminate());
  return got;
}
