// The simulated robot in its own process, as the launcher runs it, so a test
// can do to it what happens to a real bridge: stop it (SIGSTOP: the process
// frozen, its sockets open), let it go on (SIGCONT), or kill it.
import { spawn } from "node:child_process";
import { BUN } from "./app";

export interface SimulatorProcess {
  url: string;
  freeze(): void;
  thaw(): void;
  kill(): void;
}

export async function startSimulatorProcess(): Promise<SimulatorProcess> {
  const child = spawn(BUN, ["run", "src/robots/simulator/main.ts"], {
    env: { ...process.env, SIM_PORT: "0", SIM_HOST: "127.0.0.1" },
    stdio: ["ignore", "pipe", "pipe"],
  });
  const url = await new Promise<string>((ok, fail) => {
    child.stdout!.on("data", (d) => {
      const found = /rosbridge on (ws:\/\/\S+?),?(\s|$)/.exec(String(d));
      if (found) ok(found[1]!);
    });
    child.once("exit", (code) => fail(new Error(`the simulated robot exited with ${code}`)));
  });
  const signal = (name: NodeJS.Signals) => child.exitCode === null && child.signalCode === null && child.kill(name);
  return { url, freeze: () => signal("SIGSTOP"), thaw: () => signal("SIGCONT"), kill: () => signal("SIGKILL") };
}
