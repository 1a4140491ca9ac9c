// The runtime's robot for a trial: each action resolved through the plugin
// (abstract or robot-specific), dispatched over the plugin's transport, and
// its outcome reported back as the trial's action events. One path, no other.
import { resolveAction, type Plugin, type Sent } from "@/core/plugins";
import { droppedReason, olderThan, ROBOT_ACTION_FRESH_MS } from "@/core/trial/freshness";
import type { Transport } from "@/robots/transports";
import { logUnexpected } from "@/store/error-reference";
import type { CameraFrame, RobotLink, RobotReport, RobotRequest } from "./robot";
import { watchSenses } from "./robot-senses";

/** 5 frames a second unless the plugin says otherwise: what a lab's network holds for several watchers. */
const CAMERA_THROTTLE_MS = 200;

export function pluginRobot(plugin: Plugin, transport: Transport): RobotLink {
  const connecting = transport.connect().catch(() => undefined);
  const perform = async (request: RobotRequest, report: (r: RobotReport) => void) => {
    const resolved = resolveAction(plugin, request.actionType, request.parameters);
    if (resolved.status === "unsupported")
      return report({
        kind: "failed",
        actionId: request.actionId,
        reason: `${plugin.name} cannot do this: ${resolved.reason}`,
      });
    if (resolved.status === "parameter_problems") {
      return report({
        kind: "failed",
        actionId: request.actionId,
        reason: resolved.problems.map((p) => `${p.parameter}: ${p.message}`).join("; "),
      });
    }
    if (resolved.status === "runtime") return report({ kind: "completed", actionId: request.actionId });
    // The robot cannot play this sound: the wizard's browser plays it and reports its end (TrialHost.browserPlayed).
    if (resolved.status === "browser")
      return report({ kind: "dispatched", actionId: request.actionId, detail: { playedBy: "browser" } });
    await connecting;
    // The last hop before the robot: nothing older than its limit leaves (a resumed process's queue too).
    const stale = request.askedAt === undefined ? null : olderThan(ROBOT_ACTION_FRESH_MS, request.askedAt, Date.now());
    if (stale) {
      const reason = droppedReason("the robot link", stale);
      console.warn(`${plugin.name}: dropped ${request.actionType}: ${reason}`);
      return report({ kind: "not_sent", actionId: request.actionId, reason });
    }
    // What goes on the wire, recorded with the dispatch as the transport built it: the exports show the
    // message, not only the action. Once, before its outcome, even when the transport refused it unbuilt.
    let told = false;
    const dispatched = (sent: Sent | null) => {
      if (told) return;
      told = true;
      report({
        kind: "dispatched",
        actionId: request.actionId,
        detail: { robotAction: resolved.action.id, ...(sent ? { sent } : {}) },
      });
    };
    const freshUntil = request.askedAt === undefined ? undefined : request.askedAt + ROBOT_ACTION_FRESH_MS;
    const outcome = await transport.dispatch(resolved.action, resolved.parameters, {
      freshUntil,
      sending: dispatched,
      // Sent, outcome unknown: the robot's own later word on it is logged against it.
      later: (o) =>
        o.status === "completed" &&
        report({ kind: "completed", actionId: request.actionId, ...(o.detail ? { detail: o.detail } : {}) }),
    });
    dispatched(null);
    if (outcome.status === "completed")
      report({ kind: "completed", actionId: request.actionId, ...(outcome.detail ? { detail: outcome.detail } : {}) });
    else if (outcome.status === "timed_out") report({ kind: "timed_out", actionId: request.actionId });
    else report({ kind: outcome.status, actionId: request.actionId, reason: outcome.reason });
  };
  return {
    // Whatever a robot's record or transport does wrong ends as this action's failure, never as the
    // runtime's: every other trial goes on.
    perform: (request, report) =>
      void perform(request, report).catch((error: unknown) => {
        const ref = logUnexpected(error, `${plugin.name}: action ${request.actionType}`);
        report({
          kind: "failed",
          actionId: request.actionId,
          reason: `${plugin.name} could not be sent this action (reference ${ref}).`,
        });
      }),
    // Every halting action at once, not one after another: speech and animation stop with the wheels.
    halt() {
      const halting = plugin.halt?.length
        ? plugin.halt.map((id) => resolveAction(plugin, `${plugin.robotId}.${id}`, {}))
        : [resolveAction(plugin, "stop", {})];
      for (const stop of halting)
        if (stop.status === "supported")
          void transport
            .dispatch(stop.action, stop.parameters)
            .catch((error: unknown) => logUnexpected(error, `${plugin.name}: halting`));
    },
    connected: () => transport.health().state === "connected",
    onConnection(listener) {
      transport.onHealth((h) => {
        // The robot's own errors and the reason for a loss go to the runtime's log as well as to the wizard.
        const said = h.problem ?? (h.state === "connected" ? undefined : h.reason);
        if (said) console.warn(`${plugin.name}: ${said}`);
        listener(h.state === "connected", said ?? (h.state === "connected" ? undefined : h.state));
      });
    },
    onProblem(listener) {
      transport.onHealth((h) => {
        if (h.problem) listener(h.problem);
      });
    },
    watchState(listener) {
      const stops = (plugin.stateTopics ?? []).map((t) =>
        transport.subscribe(t.topic, t.messageType, (message) => listener(t.topic, message), {
          throttleRate: t.throttleRate,
        }),
      );
      return () => stops.forEach((stop) => stop());
    },
    watchSenses: (listener) => watchSenses(transport, plugin, listener),
    watchCamera(listener) {
      const { camera } = plugin;
      if (!camera) return () => {};
      return transport.subscribe(
        camera.topic,
        camera.messageType,
        (message) => {
          const frame = cameraFrame(message);
          if (frame) listener(frame);
        },
        { throttleRate: camera.throttleRate ?? CAMERA_THROTTLE_MS },
      );
    },
    close() {
      void transport.close().catch((error: unknown) => logUnexpected(error, `${plugin.name}: closing its link`));
    },
  };
}

/** A robot that cannot be reached: every action fails with the reason, at once. */
export function unavailableRobot(reason: string): RobotLink {
  return {
    perform: (request, report) => report({ kind: "failed", actionId: request.actionId, reason }),
    halt() {},
    connected: () => false,
    onConnection(listener) {
      listener(false, reason);
    },
    onProblem() {},
    watchState: () => () => {},
    watchCamera: () => () => {},
    watchSenses: () => () => {},
    close() {},
  };
}

/** A CompressedImage's bytes arrive as base64 (rosbridge's JSON) or, from some bridges, as numbers. */
function cameraFrame(message: unknown): CameraFrame | null {
  const { format, data } = (message ?? {}) as { format?: unknown; data?: unknown };
  const bytes =
    typeof data === "string"
      ? data
      : Array.isArray(data) && data.every((b) => typeof b === "number")
        ? Buffer.from(data).toString("base64")
        : null;
  return bytes ? { format: typeof format === "string" ? format : "jpeg", data: bytes } : null;
}
