// The SSH transport for NAOqi commands (qicli): one SSH connection held for
// the whole trial, each action one `exec` of its plugin-built, fully quoted
// command. Exit status 0 is completed; anything else failed with stderr.
import { readFileSync } from "node:fs";
import { Client, utils, type ConnectConfig } from "ssh2";
import { linkProblem } from "../../core/robots/link-problem";
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
import type { DispatchOptions, DispatchOutcome } from "./transport";

export interface SshOptions {
  host: string;
  port?: number;
  username: string;
  password?: string;
  privateKeyFile?: string;
  /** Reconnect delays grow from the first to the last. */
  backoffMs?: Backoff;
}

const UNREADABLE: Record<string, string> = {
  ENOENT: "there is no such file",
  EACCES: "the trial runtime may not read it",
  EISDIR: "it is a folder",
};

export class SshTransport extends LinkedTransport {
  private client: Client | null = null;
  private ready: Promise<Client | null> | null = null;
  private retry: NodeJS.Timeout | null = null;

  constructor(private readonly options: SshOptions) {
    super();
  }

  connect(): Promise<void> {
    return this.connection().then((client) => {
      if (!client)
        throw new Error(
          `cannot reach ${this.options.username}@${this.options.host} over SSH: ${this.status.reason ?? "no answer"}`,
        );
    });
  }

  async dispatch(
    action: PluginAction,
    parameters: Record<string, unknown>,
    options: DispatchOptions = {},
  ): Promise<DispatchOutcome> {
    const started = Date.now();
    const checked = checkedParameters(action, parameters);
    if (!checked.ok) return checked.outcome;
    const built = commandOf(action, checked.parameters);
    options.sending?.(built.ok ? { via: "ssh", command: built.command } : null);
    if (!built.ok) return { status: "failed", reason: built.reason };
    const timeoutMs = timeoutOf(action);
    const usable = this.settings();
    if (!usable.ok) return { status: "failed", reason: `cannot reach the robot over SSH: ${usable.reason}` };
    const client = action.retryable
      ? await untilDeadline(started + timeoutMs, () => this.connection())
      : await this.connection();
    if (!client)
      return unreached(action, started, `cannot reach the robot over SSH: ${this.status.reason ?? "no answer"}`);
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
      const failed = (error: unknown) => {
        clearTimeout(timer);
        resolve({ status: "failed", reason: `could not run the command: ${linkProblem(error)}` });
      };
      // The link may have dropped since it was handed out: ssh2 throws rather than calling back.
      try {
        client.exec(command, (error, stream) => {
          if (error) return failed(error);
          // A stream's error with no listener would be thrown, and end the runtime with every trial in it.
          stream.on("error", failed);
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
      } catch (error) {
        failed(error);
      }
    });
  }

  private connection(): Promise<Client | null> {
    if (this.status.state === "closed") return Promise.resolve(null);
    if (this.status.state === "connected" && this.client) return Promise.resolve(this.client);
    return (this.ready ??= new Promise<Client | null>((resolve) => {
      const client = new Client();
      // Why the last try failed stays told while the next one is made.
      this.setState("connecting", this.status.reason);
      let settled = false;
      const done = (value: Client | null) => {
        if (settled) return;
        settled = true;
        resolve(value);
      };
      client.on("ready", () => {
        this.client = client;
        this.status.attempts = 0;
        this.setState("connected");
        done(client);
      });
      // The first error of an attempt says why: ssh2 tells a timeout, then the connection it cut.
      let reason: string | undefined;
      const lost = () => {
        if (given) return;
        if (this.client === client) this.client = null;
        done(null);
        if (this.status.state === "closed") return;
        this.setState("disconnected", reason ?? "the robot closed the connection");
        this.reconnectLater();
      };
      client.on("error", (error) => {
        reason ??= linkProblem(error);
        lost();
      });
      client.on("close", lost);
      // A record that cannot work is not tried again on its own (trying cannot mend it): the next action
      // tries, and says why again.
      let given = false;
      const refused = (why: string) => {
        given = true;
        this.setState("disconnected", why);
        done(null);
        // ssh2 may have set its handshake timer before throwing: its error, heard above, then changes nothing.
        client.destroy();
      };
      const settings = this.settings();
      if (!settings.ok) return refused(settings.reason);
      try {
        // ssh2 throws here, not in an event, on what it cannot use (a key, a port out of range).
        client.connect(settings.value);
      } catch (error) {
        refused(linkProblem(error));
      }
      // Forgotten once settled, and never before it is kept: a record refused at once settles inside this call.
    }).finally(() => {
      this.ready = null;
    }));
  }

  /**
   * What ssh2 is given, the key read from its file; or why the robot's record cannot be used. Checked before
   * each action too: no wait and no retry can mend a record, so even a retryable action fails at once.
   */
  private settings(): { ok: true; value: ConnectConfig } | { ok: false; reason: string } {
    const { host, port = 22, username, password, privateKeyFile } = this.options;
    if (!Number.isInteger(port) || port < 1 || port > 65_535)
      return { ok: false, reason: `the SSH port ${port} is not a port number (1–65535)` };
    let privateKey: Buffer | undefined;
    if (privateKeyFile) {
      try {
        privateKey = readFileSync(privateKeyFile);
      } catch (error) {
        const code = (error as { code?: string }).code ?? "";
        return {
          ok: false,
          reason: `the SSH key file ${privateKeyFile} cannot be read: ${UNREADABLE[code] ?? "it cannot be read"}`,
        };
      }
      const parsed = utils.parseKey(privateKey);
      const key = Array.isArray(parsed) ? parsed[0] : parsed;
      if (!key || key instanceof Error || key.getPrivatePEM() === null)
        return {
          ok: false,
          reason: `the SSH key file ${privateKeyFile} does not hold a private key SSH can use${key instanceof Error ? ` (${key.message})` : ""}`,
        };
    }
    return {
      ok: true,
      value: {
        host,
        port,
        username,
        password,
        privateKey,
        readyTimeout: 5000,
        keepaliveInterval: 2000,
        keepaliveCountMax: 2,
      },
    };
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

/** The action's command line, every parameter quoted. */
function commandOf(action: PluginAction, parameters: Record<string, unknown>) {
  const outgoing = outgoingFor(action, parameters);
  if (outgoing.kind !== "ssh") return { ok: false as const, reason: `action "${action.id}" is not an SSH command` };
  return shellCommand(outgoing.command, parameters);
}
