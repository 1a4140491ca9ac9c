// What the simulated robot senses: every event its plugin declares, on the
// event's own topic with the real message type, fired by a person on its
// Robot page (a Stimulus on STIMULUS_TOPIC): a touch is pressed and released,
// a phrase is heard once, and a near event's distance is published at `hz`
// all along (far, until someone steps close), as a sonar reports.
import type { Plugin, RobotEvent } from "../../core/plugins";
import {
  distanceMessage,
  distanceOf,
  heardMessage,
  SENSABLE_TOPIC,
  type Stimulus,
  STIMULUS_TOPIC,
  sensable,
  TOUCH_MS,
  touchMessages,
} from "../../core/robots/stimulus";
import { fieldType } from "../../core/robots/messages";
import type { RosGraph } from "./graph";
import { type RobotNode, stamp } from "./nodes";
import { lookupType, populate } from "./ros-types";

const ROBOT = "robot";

export function senses(plugin: Plugin, { hz = 10 } = {}): RobotNode {
  return (graph) => {
    const events = plugin.events ?? [];
    for (const event of events) graph.declare(event.topic, event.messageType, ROBOT);
    graph.declare(STIMULUS_TOPIC, "std_msgs/msg/String", ROBOT);
    graph.declare(SENSABLE_TOPIC, "std_msgs/msg/String", ROBOT);
    const timers = new Set<NodeJS.Timeout>();
    const close = new Set<string>();
    const send = (event: RobotEvent, message: Record<string, unknown>) => publish(graph, event, message);
    const stop = graph.listen(STIMULUS_TOPIC, (m) => {
      const stimulus = parsed(String(m.data));
      const event = stimulus && events.find((e) => e.id === stimulus.event);
      if (!stimulus || !event) return;
      if ("touch" in stimulus && event.when.kind === "pressed") {
        const { pressed, released } = touchMessages(event);
        send(event, pressed);
        const timer = setTimeout(() => {
          timers.delete(timer);
          send(event, released);
        }, TOUCH_MS);
        timers.add(timer);
      } else if ("heard" in stimulus && event.when.kind === "heard")
        send(event, heardMessage(event, stimulus.heard, stimulus.confidence));
      else if ("near" in stimulus && event.when.kind === "near") {
        if (stimulus.near) close.add(event.id);
        else close.delete(event.id);
      }
    });
    const near = events.filter((e) => e.when.kind === "near");
    const readings = setInterval(() => {
      for (const event of near) send(event, distanceMessage(event, distanceOf(event, close.has(event.id))));
    }, 1000 / hz);
    const list = JSON.stringify(sensable(events));
    const announce = () => graph.publish(SENSABLE_TOPIC, { data: list });
    announce();
    const announcing = setInterval(announce, 1000);
    return () => {
      stop();
      clearInterval(readings);
      clearInterval(announcing);
      timers.forEach(clearTimeout);
    };
  };
}

/** The whole message of the event's type (every field, defaults where the stimulus says nothing), stamped now. */
function publish(graph: RosGraph, event: RobotEvent, message: Record<string, unknown>) {
  const type = lookupType(event.messageType);
  if (!type.ok) return;
  const stamped = fieldType(event.messageType, "header")
    ? { header: { stamp: stamp(), frame_id: "" }, ...message }
    : message;
  graph.publish(event.topic, populate(type.key, stamped));
}

/** A stimulus as the page sends it; anything else (another client's text) is ignored. */
function parsed(text: string): Stimulus | null {
  let value: Record<string, unknown>;
  try {
    value = JSON.parse(text) as Record<string, unknown>;
  } catch {
    return null;
  }
  if (typeof value !== "object" || value === null || typeof value.event !== "string") return null;
  const { event } = value;
  if (value.touch === true) return { event, touch: true };
  if (typeof value.near === "boolean") return { event, near: value.near };
  const { heard, confidence } = value;
  if (typeof heard === "string" && typeof confidence === "number" && confidence >= 0 && confidence <= 1)
    return { event, heard, confidence };
  return null;
}
