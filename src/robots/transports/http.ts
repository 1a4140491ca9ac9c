// The HTTP transport for robots with a REST API: each action one request
// built from its templates; 2xx is completed, anything else failed with the
// robot's answer, no answer within the plugin's timeout timed out. The API's
// base URL is probed as a heartbeat, so a robot gone away is reported at once.
import { httpRequest, type HttpRequest, type PluginAction } from "../../core/plugins";
import { linkProblem } from "../../core/robots/link-problem";
import { addressProblem, checkedParameters, LinkedTransport, timeoutOf, untilDeadline } from "./link";
import type { DispatchOptions, DispatchOutcome } from "./transport";

export interface HttpOptions {
  baseUrl: string;
  heartbeatEveryMs?: number;
}

export class HttpTransport extends LinkedTransport {
  private heartbeat: NodeJS.Timeout | null = null;

  constructor(private readonly options: HttpOptions) {
    super();
  }

  async connect() {
    if (!(await this.probe()))
      throw new Error(`cannot reach the robot's API at ${this.options.baseUrl}: ${this.status.reason ?? "no answer"}`);
    this.heartbeat ??= setInterval(() => void this.probe(), this.options.heartbeatEveryMs ?? 2000);
  }

  async dispatch(
    action: PluginAction,
    parameters: Record<string, unknown>,
    options: DispatchOptions = {},
  ): Promise<DispatchOutcome> {
    const started = Date.now();
    const checked = checkedParameters(action, parameters);
    if (!checked.ok) return checked.outcome;
    const request = this.request(action, checked.parameters);
    options.sending?.(
      request.ok
        ? { via: "http", method: request.method, url: request.url, ...(request.body ? { body: request.body } : {}) }
        : null,
    );
    if (!request.ok) return { status: "failed", reason: request.reason };
    const deadline = started + timeoutOf(action);
    const send = () =>
      fetch(request.url, {
        method: request.method,
        headers: request.body ? { "content-type": "application/json" } : undefined,
        body: request.body,
        signal: AbortSignal.timeout(Math.max(1, deadline - Date.now())),
      });
    // A retryable action is sent again while the robot's API cannot be reached, until its timeout.
    const sendUntilReached = () =>
      untilDeadline(deadline, () =>
        send().catch((error: Error) => {
          if (error.name === "TimeoutError") throw error;
          this.setState("disconnected", linkProblem(error));
          return null;
        }),
      );
    try {
      const response = action.retryable ? await sendUntilReached() : await send();
      if (!response) return { status: "timed_out", afterMs: Date.now() - started };
      const text = (await response.text()).slice(0, 500);
      if (response.ok)
        return {
          status: "completed",
          detail: {
            httpStatus: response.status,
            confirmation: { by: "http_response", confirmed: true, source: action.http!.url },
          },
        };
      return { status: "failed", reason: `the robot answered HTTP ${response.status}${text ? `: ${text}` : ""}` };
    } catch (error) {
      if ((error as Error).name === "TimeoutError") return { status: "timed_out", afterMs: Date.now() - started };
      this.setState("disconnected", linkProblem(error));
      return { status: "failed", reason: `the robot's API did not answer: ${linkProblem(error)}` };
    }
  }

  private request(action: PluginAction, parameters: Record<string, unknown>): HttpRequest {
    if (!action.http) return { ok: false, reason: `action "${action.id}" has no HTTP request` };
    const address = addressProblem("the robot's API", this.options.baseUrl, ["http:", "https:"]);
    if (address) return { ok: false, reason: address };
    return httpRequest(action.http, this.options.baseUrl, parameters);
  }

  async close() {
    if (this.heartbeat) clearInterval(this.heartbeat);
    this.setState("closed");
  }

  private async probe(): Promise<boolean> {
    const address = addressProblem("the robot's API", this.options.baseUrl, ["http:", "https:"]);
    if (address) {
      this.setState("disconnected", address);
      return false;
    }
    const started = Date.now();
    try {
      await fetch(this.options.baseUrl, { method: "GET", signal: AbortSignal.timeout(1500) });
      this.status.lastHeartbeatMs = Date.now() - started;
      this.status.attempts = 0;
      this.setState("connected");
      return true;
    } catch (error) {
      this.status.attempts++;
      this.setState("disconnected", linkProblem(error));
      return false;
    }
  }
}
