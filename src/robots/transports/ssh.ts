// The SSH transport for NAOqi commands (qicli): one SSH connection held for
// the whole trial, each action one `exec` of its plugin-built, fully quoted
// command. Exit status 0 is completed; anything else failed with stderr.
import { readFileSync } from "node:fs";
import { Client } from "ssh2";
import { outgoingFor, shellCommand, type PluginAction } from "../../core/plugins";
import {
  backoffDelay,
  checkedParameters,
  LinkedTransport,
  RECONNECT_BACKOFF,
  timeoutOf,
  unreached,
  untilDeadline,
  type Backoff,
} from "./link";
import type { DispatchOutcome } from "./transport";

export interface SshOptions {
  host: string;
  port?: number;
  username: string;
  password?: string;
  privateKeyFile?: string;
  /** Reconnect delays grow from the first to the last. */
  backoffMs?: Backoff;
}

export class SshTransport extends LinkedTransport {
  private client: Client | null = null;
  private ready: Promise<Client | null> | null = null;
  private retry: NodeJS.Timeout | null = null;

  constructor(private readonly options: SshOptions) {
    super();
  }

  connect(): Promise<void> {
    return this.connection().then((client) => {
      if (!client) throw new Error(`cannot reach ${this.options.username}@${this.options.host} over SSH`);
    });
  }

  async dispatch(action: PluginAction, parameters: Record<string, unknown>): Promise<DispatchOutcome> {
    const started = Date.now();
    const checked = checkedParameters(action, parameters);
    if (!checked.ok) return checked.outcome;
    const outgoing = outgoingFor(action, checked.parameters);
    if (outgoing.kind !== "ssh") return { status: "failed", reason: `action "${action.id}" is not an SSH command` };
    const built = shellCommand(outgoing.command, checked.parameters);
    if (!built.ok) return { status: "failed", reason: built.reason };
    const timeoutMs = timeoutOf(action);
    const client = action.retryable
      ? await untilDeadline(started + timeoutMs, () => this.connection())
      : await this.connection();
    if (!client) return unreached(action, started, "robot not reachable over SSH");
    // The timeout is the command's: a slow first handshake does not eat into it.
    return this.run(client, built.command, timeoutMs, Date.now());
  }

  async close() {
    this.setState("closed");
    if (this.retry) clearTimeout(this.retry);
    this.client?.end();
  }

  private run(client: Client, command: string, timeoutMs: number, started: number): Promise<DispatchOutcome> {
    return new Promise((resolve) => {
      const timer = setTimeout(() => resolve({ status: "timed_out", afterMs: Date.now() - started }), timeoutMs);
      client.exec(command, (error, stream) => {
        if (error) {
          clearTimeout(timer);
          return resolve({ status: "failed", reason: `could not run the command: ${error.message}` });
        }
        let stderr = "";
        stream.stderr.on("data", (d: Buffer) => (stderr += d.toString()));
        stream.on("data", () => {});
        stream.on("close", (code: number | null) => {
          clearTimeout(timer);
          // The command returns when the robot has done it (qicli call blocks): its exit confirms.
          if (code === 0)
            resolve({
              status: "completed",
              detail: { exitCode: 0, confirmation: { by: "command_exit", confirmed: true } },
            });
          else
            resolve({
              status: "failed",
              reason: `the robot refused the command (exit ${code ?? "unknown"})${stderr.trim() ? `: ${stderr.trim()}` : ""}`,
            });
        });
      });
    });
  }

  private connection(): Promise<Client | null> {
    if (this.status.state === "closed") return Promise.resolve(null);
    if (this.status.state === "connected" && this.client) return Promise.resolve(this.client);
    this.ready ??= new Promise((resolve) => {
      const client = new Client();
      this.setState("connecting");
      let settled = false;
      const done = (value: Client | null) => {
        if (settled) return;
        settled = true;
        this.ready = null;
        resolve(value);
      };
      client.on("ready", () => {
        this.client = client;
        this.status.attempts = 0;
        this.setState("connected");
        done(client);
      });
      const lost = () => {
        if (this.client === client) this.client = null;
        done(null);
        if (this.status.state === "closed") return;
        this.setState("disconnected");
        this.reconnectLater();
      };
      client.on("error", lost);
      client.on("close", lost);
      const { host, port = 22, username, password, privateKeyFile } = this.options;
      client.connect({
        host,
        port,
        username,
        password,
        privateKey: privateKeyFile ? readFileSync(privateKeyFile) : undefined,
        readyTimeout: 5000,
        keepaliveInterval: 2000,
        keepaliveCountMax: 2,
      });
    });
    return this.ready;
  }

  private reconnectLater() {
    if (this.retry) return;
    const delay = backoffDelay(this.status.attempts++, this.options.backoffMs ?? RECONNECT_BACKOFF);
    this.retry = setTimeout(() => {
      this.retry = null;
      void this.connection();
    }, delay);
  }
}
