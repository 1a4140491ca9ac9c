// The SSH transport for NAOqi commands (qicli): one SSH connection held for
// the whole trial, each action one `exec` of its plugin-built, fully quoted
// command. Exit status 0 is completed; anything else failed with stderr.
import { readFileSync } from "node:fs";
import { Client } from "ssh2";
import { outgoingFor, shellCommand, validateParameters, withDefaults, type PluginAction } from "../../core/plugins";
import { DEFAULT_TIMEOUT_MS, untilDeadline, type DispatchOutcome, type Health, type Transport } from "./transport";

export interface SshOptions {
  host: string;
  port?: number;
  username: string;
  password?: string;
  privateKeyFile?: string;
  /** Reconnect delays grow from the first to the last. */
  backoffMs?: { first: number; max: number };
}

export class SshTransport implements Transport {
  private client: Client | null = null;
  private status: Health = { state: "disconnected", since: Date.now(), attempts: 0, lastHeartbeatMs: null };
  private readonly listeners = new Set<(health: Health) => void>();
  private ready: Promise<Client | null> | null = null;
  private retry: NodeJS.Timeout | null = null;

  constructor(private readonly options: SshOptions) {}

  connect(): Promise<void> {
    return this.connection().then((client) => {
      if (!client) throw new Error(`cannot reach ${this.options.username}@${this.options.host} over SSH`);
    });
  }

  health(): Health {
    return { ...this.status };
  }

  onHealth(listener: (health: Health) => void) {
    this.listeners.add(listener);
    return () => void this.listeners.delete(listener);
  }

  async dispatch(action: PluginAction, parameters: Record<string, unknown>): Promise<DispatchOutcome> {
    const started = Date.now();
    const problems = validateParameters(action.parameterSchema, parameters);
    if (problems.length) return { status: "failed", reason: problems.map((p) => p.message).join("; ") };
    const outgoing = outgoingFor(action, parameters);
    if (outgoing.kind !== "ssh") return { status: "failed", reason: `action "${action.id}" is not an SSH command` };
    const built = shellCommand(outgoing.command, withDefaults(action.parameterSchema, parameters));
    if (!built.ok) return { status: "failed", reason: built.reason };
    const timeoutMs = action.timeout ?? DEFAULT_TIMEOUT_MS;
    // A retryable action waits for the robot to come back within its timeout; any other fails at once.
    const client = action.retryable ? await untilDeadline(started + timeoutMs, () => this.connection()) : await this.connection();
    if (!client) return action.retryable ? { status: "timed_out", afterMs: Date.now() - started } : { status: "failed", reason: "robot not reachable over SSH" };
    // The timeout is the command's: a slow first handshake does not eat into it.
    return this.run(client, built.command, timeoutMs, Date.now());
  }

  /** SSH carries commands, not robot state: state comes over rosbridge. */
  subscribe() {
    return () => {};
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
          if (code === 0) resolve({ status: "completed", detail: { exitCode: 0 } });
          else resolve({ status: "failed", reason: `the robot refused the command (exit ${code ?? "unknown"})${stderr.trim() ? `: ${stderr.trim()}` : ""}` });
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
      client.connect({ host, port, username, password, privateKey: privateKeyFile ? readFileSync(privateKeyFile) : undefined, readyTimeout: 5000, keepaliveInterval: 2000, keepaliveCountMax: 2 });
    });
    return this.ready;
  }

  private reconnectLater() {
    if (this.retry) return;
    const { first, max } = this.options.backoffMs ?? { first: 250, max: 5000 };
    const delay = Math.min(max, first * 2 ** this.status.attempts++);
    this.retry = setTimeout(() => {
      this.retry = null;
      void this.connection();
    }, delay);
  }

  private setState(state: Health["state"]) {
    if (this.status.state === state) return;
    this.status = { ...this.status, state, since: Date.now() };
    this.listeners.forEach((listener) => listener(this.health()));
  }
}
