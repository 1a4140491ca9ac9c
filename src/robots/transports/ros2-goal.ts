// The rosbridge side of what a plugin action can be besides a publish or a
// service call: a ROS 2 action goal (through roslib's Action: rosbridge's
// send_action_goal, action_feedback, action_result, cancel_action_goal), a
// turn held then stopped, and one message read from a topic.
import * as ROSLIB from "roslib";
import type { JsonObject, JsonValue } from "../../core/plugins";
import type { DispatchOutcome } from "./transport";

/**
 * Sends the goal and waits for its result. Completed only when the action
 * server says it succeeded; a goal still running at the deadline is cancelled
 * (so the robot does not carry on unwatched) and reported as timed out.
 */
export function sendGoal(
  ros: ROSLIB.Ros,
  goal: { action: string; actionType: string; goal: JsonValue },
  deadline: number,
): Promise<DispatchOutcome> {
  const started = Date.now();
  const client = new ROSLIB.Action<JsonValue, unknown, unknown>({
    ros,
    name: goal.action,
    actionType: goal.actionType,
  });
  return new Promise((resolve) => {
    let feedback = 0;
    let lastFeedback: unknown;
    const timer = setTimeout(
      () => {
        if (id) client.cancelGoal(id);
        done({ status: "timed_out", afterMs: Date.now() - started });
      },
      Math.max(0, deadline - started),
    );
    let settled = false;
    const done = (outcome: DispatchOutcome) => {
      if (settled) return;
      settled = true;
      clearTimeout(timer);
      // roslib leaves its listener for the goal's answers on the connection.
      if (id) ros.removeAllListeners(id);
      resolve(outcome);
    };
    const id = client.sendGoal(
      goal.goal,
      (result) =>
        done({
          status: "completed",
          detail: {
            action: goal.action,
            result,
            feedback,
            lastFeedback,
            // The action server's own result: the robot says it is done.
            confirmation: { by: "action_result", confirmed: true, source: goal.action },
          },
        }),
      (values) => {
        feedback++;
        lastFeedback = values;
      },
      (error) =>
        done({ status: "failed", reason: `the ROS 2 action ${goal.action} did not succeed: ${goalError(error)}` }),
    );
  });
}

/** roslib's failure is a GoalError's text ("GoalError: Action was aborted: ..."). */
const goalError = (error: unknown) => String(error).replace(/^GoalError:\s*/, "");

/** Publishes the turn, then the stop once the turn is done; completed when the stop is sent. */
export function holdThenStop(
  publish: (message: JsonValue) => boolean,
  motion: { message: JsonValue; stopAfterMs: number; stop: JsonValue; topic: string },
): Promise<DispatchOutcome> {
  publish(motion.message);
  return new Promise((resolve) => {
    setTimeout(() => {
      resolve(
        publish(motion.stop)
          ? {
              status: "completed",
              // Turned for the time asked and stopped: sent, not confirmed by the robot.
              detail: {
                topic: motion.topic,
                turnedForMs: motion.stopAfterMs,
                confirmation: { by: "delivered", confirmed: false },
              },
            }
          : { status: "failed", reason: `the robot was lost before the stop was sent on ${motion.topic}` },
      );
    }, motion.stopAfterMs);
  });
}

/** The next message of the topic, read; timed out if none comes by the deadline. */
export function readOnce(
  ros: ROSLIB.Ros,
  reading: { topic: string; messageType: string; read: (message: unknown) => JsonObject },
  deadline: number,
): Promise<DispatchOutcome> {
  const started = Date.now();
  const topic = new ROSLIB.Topic({
    ros,
    name: reading.topic,
    messageType: reading.messageType,
    reconnect_on_close: false,
  });
  return new Promise((resolve) => {
    const listener = (message: unknown) =>
      finish({
        status: "completed",
        // The robot's own message answered the reading.
        detail: {
          topic: reading.topic,
          state: reading.read(message),
          confirmation: { by: "done_topic", confirmed: true, source: reading.topic },
        },
      });
    const timer = setTimeout(
      () => finish({ status: "timed_out", afterMs: Date.now() - started }),
      Math.max(0, deadline - started),
    );
    const finish = (outcome: DispatchOutcome) => {
      clearTimeout(timer);
      topic.unsubscribe(listener);
      resolve(outcome);
    };
    topic.subscribe(listener);
  });
}
