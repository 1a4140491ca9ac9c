// ROS 2 action goals as rosbridge (ROS 2) carries them: send_action_goal in,
// action_feedback while the goal runs (when asked for), one action_result at
// the end with the goal's status (4 succeeded, 5 canceled, 6 aborted), and
// cancel_action_goal to stop a goal by its id. A goal that cannot be sent (no
// such action, a wrong type, a bad goal) is answered with result false and
// the reason, as rosbridge's failure reply does.
import type { RosGraph } from "./graph";
import { lookupType, populateGoal } from "./ros-types";

type Message = Record<string, unknown>;

export const GOAL_STATUS = { succeeded: 4, canceled: 5, aborted: 6 } as const;

export class ActionGoals {
  private readonly running = new Map<string, () => void>();
  private closed = false;

  constructor(
    private readonly graph: RosGraph,
    private readonly send: (message: Message) => void,
    private readonly log: (text: string) => void,
  ) {}

  goal(m: Message) {
    const id = String(m.id ?? "");
    const action = String(m.action ?? "");
    const result = (values: unknown, status: number, ok: boolean) =>
      this.closed || this.send({ op: "action_result", id, action, values, status, result: ok });
    const fail = (reason: string) => {
      this.log(`send_action_goal ${action}: ${reason}`);
      result(reason, GOAL_STATUS.aborted, false);
    };
    const server = this.graph.actions.get(action);
    if (!server) return fail(`Action ${action} does not exist`);
    const type = lookupType(m.action_type, "action");
    if (!type.ok) return fail(type.reason);
    if (type.key !== server.typeKey) return fail(`Action ${action} is of type ${server.typeKey}, not ${type.key}`);
    let goal: Message;
    try {
      goal = populateGoal(type.key, m.args);
    } catch (error) {
      return fail((error as Error).message);
    }
    let cancel!: () => void;
    const cancelled = new Promise<void>((resolve) => (cancel = resolve));
    let over = false;
    this.running.set(id, () => {
      over = true;
      cancel();
      result({}, GOAL_STATUS.canceled, true);
    });
    const feedback = (values: Message) => {
      if (!over && m.feedback === true) this.send({ op: "action_feedback", id, action, values });
    };
    server.handler(goal, { feedback, cancelled }).then(
      (values) => {
        if (over) return;
        over = true;
        this.running.delete(id);
        result(values, GOAL_STATUS.succeeded, true);
      },
      (error: Error) => {
        if (over) return;
        over = true;
        this.running.delete(id);
        this.log(`action ${action} aborted: ${error.message}`);
        result({}, GOAL_STATUS.aborted, true);
      },
    );
  }

  cancel(m: Message) {
    const id = String(m.id ?? "");
    const stop = this.running.get(id);
    this.running.delete(id);
    stop?.();
  }

  /** The connection closed: its goals stop (rosbridge cancels a client's goals when it leaves). */
  close() {
    this.closed = true;
    for (const stop of this.running.values()) stop();
    this.running.clear();
  }
}
