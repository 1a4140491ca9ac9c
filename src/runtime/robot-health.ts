// A registered robot's health, written to its record as the runtime sees it:
// connected or not, its battery, and when it last answered. The admin page
// reads it from there, so it is true whichever runtime process drives the robot.
import { batteryPercent } from "@/core/robots/live-state";
import { recordHealth } from "@/robots/registry";
import type { Database } from "@/store/client";
import { logUnexpected } from "@/store/error-reference";
import { oneAfterAnotherBy } from "@/core/one-after-another";
import type { RobotLink } from "./robot";

/** At most one battery write per robot per this long: the record is for people, not a sample log. */
const BATTERY_EVERY_MS = 10_000;

/**
 * The process's writer of robots' health records. Each robot's writes go one after another (a link that
 * drops and comes back at once must not leave its record saying disconnected: writes at once would go out
 * on several of the pool's connections and commit in any order), and `settled` waits for every write asked
 * for so far: the runtime, stopping, awaits it before its pool ends, so the "disconnected" its closing links
 * write is on their records, not an error in the log.
 */
export function robotHealth(db: Database) {
  const inTurn = oneAfterAnotherBy<string>();
  const writing = new Set<Promise<void>>();
  const write = (robotId: string, health: { connected?: boolean; battery?: number }) => {
    const done = inTurn(robotId, () => recordHealth(db, robotId, health)).then(
      () => {},
      (error: unknown) => void logUnexpected(error, "recording a robot's health"),
    );
    writing.add(done);
    void done.finally(() => writing.delete(done));
  };
  return {
    /**
     * The link, recording its health on the robot's record. `moreState`: state topics beyond the plugin's
     * (the simulated robot's own report) that the trial host should also see.
     */
    withHealth: (
      robotId: string,
      link: RobotLink,
      moreState?: (listener: (topic: string, message: unknown) => void) => () => void,
    ): RobotLink => withHealth((health) => write(robotId, health), link, moreState),
    settled: async () => {
      await Promise.all(writing);
    },
  };
}

function withHealth(
  write: (health: { connected?: boolean; battery?: number }) => void,
  link: RobotLink,
  moreState?: (listener: (topic: string, message: unknown) => void) => () => void,
): RobotLink {
  // Closed, the link's record says disconnected once, as it closes; the socket's own close, heard after
  // (as the process stops, once the database is closed too), is no news to the record. Its listeners
  // still hear it: the wizard's page says the robot was released.
  let closed = false;
  link.onConnection((connected) => closed || write({ connected }));
  let batteryAt = Number.NEGATIVE_INFINITY;
  const stopBattery = link.watchState((_, message) => {
    const battery = batteryPercent(message);
    if (battery === null || Date.now() - batteryAt < BATTERY_EVERY_MS) return;
    batteryAt = Date.now();
    write({ connected: true, battery });
  });
  return {
    perform: (request, report) => link.perform(request, report),
    halt: () => link.halt(),
    connected: () => link.connected(),
    onConnection: (listener) => link.onConnection(listener),
    onProblem: (listener) => link.onProblem(listener),
    watchCamera: (listener) => link.watchCamera(listener),
    watchSenses: (listener) => link.watchSenses(listener),
    watchState(listener) {
      const stops = [link.watchState(listener), ...(moreState ? [moreState(listener)] : [])];
      return () => stops.forEach((stop) => stop());
    },
    close() {
      closed = true;
      stopBattery();
      link.close();
      write({ connected: false });
    },
  };
}
