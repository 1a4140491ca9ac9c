// One robot, two channels: its own transport (rosbridge or HTTP) and SSH for
// the plugin's NAOqi commands. The trial runtime sees one transport. An action
// whose way this server has no address for fails at once, with the reason the
// designer gave for calling it not runnable.
import { isSshCommand, unreachable, type Channels, type Plugin, type PluginAction } from "../../core/plugins";
import type { DispatchOptions, DispatchOutcome, Health, Transport } from "./transport";

export class RoutedTransport implements Transport {
  constructor(
    private readonly plugin: Plugin,
    private readonly channels: Channels,
    private readonly primary: Transport,
    private readonly ssh: Transport | null,
  ) {}

  async connect() {
    // SSH may come later (the robot's password set after start); the robot's own transport decides.
    void this.ssh?.connect().catch(() => undefined);
    await this.primary.connect();
  }

  dispatch(
    action: PluginAction,
    parameters: Record<string, unknown>,
    options?: DispatchOptions,
  ): Promise<DispatchOutcome> {
    const closed = unreachable(this.plugin, action, this.channels);
    if (closed)
      return Promise.resolve({
        status: "failed",
        reason: `"${action.name}" cannot run on ${this.plugin.name}: ${closed}`,
      });
    return (isSshCommand(action) ? this.ssh! : this.primary).dispatch(action, parameters, options);
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
