// A protocol of one step for runtime tests, as an experiment version stores it:
// the NAO6 plugin's actions, each named by its id.
import { DOCUMENT_VERSION } from "../../src/core/protocol/document";

export function oneStep(actions: Array<{ id: string; type: string; parameters?: Record<string, unknown> }>) {
  return {
    schemaVersion: DOCUMENT_VERSION as typeof DOCUMENT_VERSION,
    experiment: { id: "e", name: "Greeting", description: "", robotId: "nao6-ros2" },
    steps: [
      {
        id: "s1",
        name: "Greet",
        description: "",
        actions: actions.map(({ id, type, parameters = {} }) => ({
          id,
          type,
          name: id,
          parameters,
          parallelGroup: null,
        })),
      },
    ],
  };
}
