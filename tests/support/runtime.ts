// A trial runtime process (Bun) against a test database, as the launcher starts it.
import { spawn, type ChildProcess } from "node:child_process";
import { withRuntimeEngine } from "../../src/launcher/runtime-engine";
import { freePort } from "../../src/store/embedded";
import { BUN } from "./app";

export async function startRuntime(
  databaseUrl: string,
  secret: string,
  /** More settings, e.g. the robot's and the simulated robot's addresses. */
  env: Record<string, string> = {},
): Promise<{ url: string; child: ChildProcess }> {
  const port = await freePort();
  const child = spawn(BUN, ["run", "src/runtime/main.ts"], {
    env: {
      ...withRuntimeEngine(process.env),
      DATABASE_URL: databaseUrl,
      BETTER_AUTH_SECRET: secret,
      HRI_RUNTIME_PORT: String(port),
      HOST: "127.0.0.1",
      ...env,
    },
    stdio: ["ignore", "pipe", "pipe"],
  });
  await new Promise<void>((ok, fail) => {
    child.stdout!.on("data", (d) => String(d).includes("listening") && ok());
    child.once("exit", (code) => fail(new Error(`runtime exited with ${code}`)));
  });
  return { url: `ws://127.0.0.1:${port}`, child };
}
