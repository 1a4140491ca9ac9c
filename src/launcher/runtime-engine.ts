// The trial runtime's JavaScript engine settings, for whoever starts the
// process (the launcher, the tests' and the benches' harnesses): Bun reads
// them from the environment as it starts, so the process cannot set them
// itself.
//
// JavaScriptCore's top compiler tier (FTL) is off. It recompiles a function
// once it has run very often; a wizard's command runs through many small
// functions that each reach that count at their own moment, so its compiles
// went on through a whole session (30 to 50 in each thousand lines, measured
// with BUN_JSC_reportFTLCompileTimes), and a line that met one waited. On two
// cores: one trial's p99 4.5–6.0 ms with it, 3.5–4.8 ms without, for the same
// CPU per line and the same throughput (20 wizards: 2,208 and 2,228 actions/s).
// Long work it speeds up (folding a trial of 100k events as it opens) takes
// ~15% longer in the tier below it (DFG), which is kept.

/** The engine settings the trial runtime starts with, unless the environment sets them: a value set there wins. */
const RUNTIME_ENGINE = { BUN_JSC_useFTLJIT: "false" } as const;

/** The environment to start the trial runtime in: `env`, with the engine settings it does not set itself. */
export function withRuntimeEngine<Env extends Record<string, string | undefined>>(env: Env) {
  return { ...RUNTIME_ENGINE, ...env };
}
