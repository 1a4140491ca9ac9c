// The simulated robot's SSH side: a real SSH server (ssh2's), so the runtime
// reaches it with its real SSH transport as it would a NAO. Each exec is one
// qicli command, answered by the pure NAOqi stand-in (core/robots/naoqi.ts)
// on the same robot state the rosbridge side publishes. A fresh host key is
// made at every start; one user logs in with a password the launcher makes.
import { createHash, timingSafeEqual } from "node:crypto";
import { Server, utils } from "ssh2";
import { naoqiCommand } from "../../core/robots/naoqi";
import type { RobotState } from "../../core/robots/robot-state";

export interface SimulatedSshOptions {
  host: string;
  /** 0 picks a free port. */
  port: number;
  username: string;
  password: string;
}

export interface SimulatedSsh {
  port: number;
  /** Every command run, with its exit status, in order. */
  commands: Array<{ command: string; exitCode: number }>;
  close(): Promise<void>;
}

const digest = (text: string) => createHash("sha256").update(text).digest();

/**
 * A fresh ed25519 host key that ssh2 itself can read. Its generator writes the public key as a number, so one
 * whose first byte is zero comes out 31 bytes long and is refused as malformed (about one key in 200: the
 * simulated robot then failed to start now and again); such a key is made again.
 */
export function hostKey(): string {
  for (;;) {
    const key = utils.generateKeyPairSync("ed25519").private;
    if (!(utils.parseKey(key) instanceof Error)) return key;
  }
}
const same = (a: string, b: string) => timingSafeEqual(digest(a), digest(b));

export async function startSimulatedSsh(options: SimulatedSshOptions, state: RobotState): Promise<SimulatedSsh> {
  const commands: SimulatedSsh["commands"] = [];
  const clients = new Set<{ end(): unknown }>();
  const server = new Server({ hostKeys: [hostKey()] }, (client) => {
    clients.add(client);
    client.on("close", () => clients.delete(client));
    client.on("error", () => client.end());
    client.on("authentication", (auth) => {
      if (auth.method === "password" && same(auth.username, options.username) && same(auth.password, options.password))
        return auth.accept();
      auth.reject(["password"]);
    });
    client.on("ready", () =>
      client.on("session", (acceptSession) => {
        const session = acceptSession();
        // A NAO's shell would open too; the simulated one only runs commands.
        session.on("pty", (_accept, reject) => reject?.());
        session.on("shell", (_accept, reject) => reject());
        session.on("exec", (accept, _reject, { command }) => {
          const reply = naoqiCommand(command);
          Object.assign(state, reply.change);
          commands.push({ command, exitCode: reply.exitCode });
          const channel = accept();
          if (reply.stdout) channel.write(reply.stdout);
          if (reply.stderr) channel.stderr.write(reply.stderr);
          channel.exit(reply.exitCode);
          channel.end();
        });
      }),
    );
  });
  await new Promise<void>((resolve, reject) => {
    server.once("error", reject);
    server.listen(options.port, options.host, () => resolve());
  });
  return {
    port: (server.address() as { port: number }).port,
    commands,
    close: () =>
      new Promise<void>((resolve) => {
        clients.forEach((c) => c.end());
        server.close(() => resolve());
      }),
  };
}
