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

/** Each engine setting the trial runtime starts with, unless the environment sets it: a value set there wins. */
const RUNTIME_ENGINE = { BUN_JSC_useFTLJIT: "false" } as const;

/** The engine settings to start the runtime with, those `env` does not set itself. */
export function runtimeEngine(env: Record<string, string | undefined>): Record<string, string> {
  return Object.fromEntries(Object.entries(RUNTIME_ENGINE).filter(([name]) => env[name] === undefined));
}
