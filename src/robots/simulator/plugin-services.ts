// The services a plugin calls (its service dispatches, HRIStudio's payloadMapping
// of type "service" among them), offered by the simulated robot so a pilot
// trial gets the answer rosbridge would carry: the service type's response,
// reporting success where the type has a success field. A templated name is
// offered under every name its fixed values make; a name open to any text,
// or a type the simulator does not know, is not offered, and a call to it is
// answered as rosbridge answers a service that does not exist.
import { dispatchName, reachableNames, type Plugin } from "../../core/plugins";
import type { RobotNode } from "./nodes";
import { ConversionError, lookupType, populateResponse } from "./ros-types";

export function pluginServices(plugin: Plugin): RobotNode {
  return (graph) => {
    for (const action of plugin.actions) {
      const ros2 = action.ros2;
      if (!ros2 || !("service" in ros2)) continue;
      const type = lookupType(ros2.serviceType ?? ros2.messageType, "srv");
      const reach = reachableNames(dispatchName(action)!, action.parameterSchema);
      if (!type.ok || !("names" in reach)) continue;
      const reply = answer(type.key);
      for (const name of reach.names) if (!graph.services.has(name)) graph.offer(name, type.spelling, () => reply);
    }
    return () => {};
  };
}

function answer(typeKey: string): Record<string, unknown> {
  try {
    return populateResponse(typeKey, { success: true });
  } catch (error) {
    // A response without a success field (std_srvs/Empty): the type's empty response.
    if (error instanceof ConversionError) return populateResponse(typeKey, {});
    throw error;
  }
}
