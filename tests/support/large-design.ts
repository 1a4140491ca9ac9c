// The largest designs the limits allow, for the tests and the bench that
// import, save, publish and run them: steps of waves, each action named so
// the file is as large as a real one of that many actions would be.

/** `steps` steps of `actions` waves each, as the designer saves them. */
export function largeSteps(steps: number, actions: number) {
  return Array.from({ length: steps }, (_, s) => ({
    name: `Step ${s + 1}`,
    actions: Array.from({ length: actions }, (_, a) => ({ type: "wave", name: `Wave ${s + 1}.${a + 1}` })),
  }));
}

/** The same design as an experiment file, written compactly (an exported file is indented). */
export function largeExperimentFile(steps: number, actions: number, name = "Large design"): string {
  return JSON.stringify({
    format: "hristudio.experiment",
    formatVersion: 2,
    experiment: { name, description: "", robot: "nao6-ros2" },
    steps: largeSteps(steps, actions).map((step, s) => ({ key: `step-${s + 1}`, ...step })),
  });
}
