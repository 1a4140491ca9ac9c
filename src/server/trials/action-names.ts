// The names of a trial's action types as the designer's library showed them:
// the robot's own actions named by the plugin document the trial runs with,
// and its events ("Head touched") for the wizard's wait panel. Without that
// document (gone, or no plugin installed) the built-in blocks still have
// their names, the robot's actions read as words and its events as ids.
import { actionNamesOf, type ActionNames } from "@/core/designer/action-name";
import { type EventNames, eventNamesOf } from "@/core/plugins";
import type { Database } from "@/store/client";
import { trialPlugin } from "@/robots/trial-plugin";

export async function trialPluginNames(
  db: Pick<Database, "select">,
  trialId: string,
): Promise<{ actionNames: ActionNames; eventNames: EventNames }> {
  const chosen = await trialPlugin(db, trialId);
  const plugin = chosen.ok ? chosen.plugin : null;
  return { actionNames: actionNamesOf(plugin), eventNames: eventNamesOf(plugin) };
}

export async function trialActionNames(db: Pick<Database, "select">, trialId: string): Promise<ActionNames> {
  return (await trialPluginNames(db, trialId)).actionNames;
}
