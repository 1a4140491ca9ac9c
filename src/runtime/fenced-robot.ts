// A trial's robot as its host drives it: each action is sent only while this
// process still owns the trial (`TrialLocks.owns`), so a process that lost
// the trial (its lock connection ended, the database restarted, the process
// frozen for longer than its lease) sends nothing before it knows. An
// emergency stop is never held back: any runtime may stop a robot.
import type { RobotLink } from "./robot";

const NOT_OWNER =
  "Not sent: this runtime process could not confirm it still runs the trial (its database connection was lost, or another process took the trial over), so the robot was not told.";

export function fencedRobot(link: RobotLink, owns: () => Promise<boolean>): RobotLink {
  return {
    ...link,
    perform(request, report) {
      // In the order asked: each waits on the same answer, resolved in turn.
      void owns().then(
        (ok) =>
          ok
            ? link.perform(request, report)
            : report({ kind: "not_sent", actionId: request.actionId, reason: NOT_OWNER }),
        () => report({ kind: "not_sent", actionId: request.actionId, reason: NOT_OWNER }),
      );
    },
  };
}
