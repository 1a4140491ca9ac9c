// One robot, two channels: rosbridge for topics and services, SSH for the
// plugin's NAOqi commands. The trial runtime sees one transport.
import type { PluginAction } from "../../core/plugins";
import type { DispatchOutcome, Health, Transport } from "./transport";

const overSsh = (action: PluginAction) =>
  !!action.ros2 && "payloadMapping" in action.ros2 && action.ros2.payloadMapping.type === "ssh";

export class RoutedTransport implements Transport {
  constructor(
    private readonly primary: Transport,
    private readonly ssh: Transport | null,
  ) {}

  async connect() {
    // SSH may come later (the robot's password set after start); rosbridge decides.
    void this.ssh?.connect().catch(() => undefined);
    await this.primary.connect();
  }

  dispatch(action: PluginAction, parameters: Record<string, unknown>): Promise<DispatchOutcome> {
    if (!overSsh(action)) return this.primary.dispatch(action, parameters);
    if (!this.ssh)
      return Promise.resolve({
        status: "failed",
        reason: `"${action.name}" needs SSH to the robot: set HRI_ROBOT_SSH_HOST (see docs/robot-setup.md)`,
      });
    return this.ssh.dispatch(action, parameters);
  }

  subscribe(...args: Parameters<Transport["subscribe"]>) {
    return this.primary.subscribe(...args);
  }

  health(): Health {
    return this.primary.health();
  }

  onHealth(listener: (health: Health) => void) {
    return this.primary.onHealth(listener);
  }

  async close() {
    await Promise.all([this.primary.close(), this.ssh?.close()]);
  }
}
