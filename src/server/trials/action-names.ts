// The names of a trial's action types as the designer's library showed them:
// the robot's own actions named by the plugin document the trial runs with.
// Without that document (gone, or no plugin installed) the built-in blocks
// still have their names and the robot's actions read as words.
import { actionNamesOf, type ActionNames } from "@/core/designer/action-name";
import type { Database } from "@/store/client";
import { trialPlugin } from "@/robots/trial-plugin";

export async function trialActionNames(db: Pick<Database, "select">, trialId: string): Promise<ActionNames> {
  const chosen = await trialPlugin(db, trialId);
  return actionNamesOf(chosen.ok ? chosen.plugin : null);
}
