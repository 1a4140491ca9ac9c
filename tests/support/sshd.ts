// A real OpenSSH server on loopback for the SSH transport's tests, with a
// recording `qicli` stand-in first on the PATH of every session.
import { spawn, spawnSync, type ChildProcess } from "node:child_process";
import { chmodSync, existsSync, readFileSync, writeFileSync } from "node:fs";
import { userInfo } from "node:os";
import { join } from "node:path";
import { freePort } from "../../src/store/embedded";
import { scratchFolder } from "./scratch";

export const SSHD = "/usr/sbin/sshd";

export interface TestSshd {
  port: number;
  username: string;
  keyFile: string;
  /** Every qicli call, one JSON argv per line. */
  calls(): string[][];
  stop(): void;
  restart(): Promise<void>;
}

export async function startSshd(): Promise<TestSshd> {
  if (!existsSync(SSHD))
    throw new Error(
      "openssh-server is needed for the SSH tests: apt-get install openssh-server (npm test installs it as root).",
    );
  const dir = scratchFolder("sshd-");
  chmodSync(dir, 0o755);
  const key = (name: string, type: string) =>
    spawnSync("ssh-keygen", ["-q", "-t", type, "-N", "", "-f", join(dir, name)]);
  key("host_key", "ed25519");
  key("client_key", "ed25519");
  writeFileSync(join(dir, "authorized_keys"), readFileSync(join(dir, "client_key.pub")));
  const bin = join(dir, "bin");
  spawnSync("mkdir", ["-p", bin]);
  const calls = join(dir, "qicli-calls.jsonl");
  // The stand-in records its arguments exactly; "fail" and "slow" in them act as a robot would.
  writeFileSync(
    join(bin, "qicli"),
    `#!/usr/bin/env python3\nimport json, sys, time\nopen(${JSON.stringify(calls)}, "a").write(json.dumps(sys.argv[1:]) + "\\n")\nif "fail" in sys.argv: print("ALMotion: motors are off", file=sys.stderr); sys.exit(2)\nif "slow" in sys.argv: time.sleep(5)\n`,
    { mode: 0o755 },
  );
  const port = await freePort();
  writeFileSync(
    join(dir, "sshd_config"),
    [
      `Port ${port}`,
      "ListenAddress 127.0.0.1",
      `HostKey ${join(dir, "host_key")}`,
      `AuthorizedKeysFile ${join(dir, "authorized_keys")}`,
      `PidFile ${join(dir, "sshd.pid")}`,
      "PasswordAuthentication no",
      "KbdInteractiveAuthentication no",
      "PermitRootLogin prohibit-password",
      "UsePAM no",
      "StrictModes no",
      // A robot's shell, not this machine's: no login scripts (a ~/.bashrc here runs pyenv, which can hang on a stale lock).
      `SetEnv PATH=${bin}:/usr/bin:/bin HOME=${dir}`,
    ].join("\n"),
  );
  spawnSync("mkdir", ["-p", "/run/sshd"]);
  let child = await listen(join(dir, "sshd_config"));
  return {
    port,
    username: userInfo().username,
    keyFile: join(dir, "client_key"),
    calls: () =>
      existsSync(calls)
        ? readFileSync(calls, "utf8")
            .trim()
            .split("\n")
            .filter(Boolean)
            .map((l) => JSON.parse(l) as string[])
        : [],
    // The listener and every per-connection sshd below it: a robot gone from the network.
    stop: () => killTree(child.pid!),
    // The robot back on the network, at the same address.
    restart: async () => void (child = await listen(join(dir, "sshd_config"))),
  };
}

async function listen(config: string): Promise<ChildProcess> {
  const child = spawn(SSHD, ["-D", "-e", "-f", config], { stdio: ["ignore", "ignore", "pipe"] });
  let log = "";
  child.stderr!.on("data", (d) => (log += d));
  await new Promise<void>((ok, fail) => {
    const timer = setTimeout(() => fail(new Error(`sshd did not start: ${log}`)), 10_000);
    child.stderr!.on("data", () => log.includes("Server listening") && (clearTimeout(timer), ok()));
    child.once("exit", (code) => fail(new Error(`sshd exited with ${code}: ${log}`)));
  });
  return child;
}

function killTree(pid: number) {
  const children = spawnSync("ps", ["-o", "pid=", "--ppid", String(pid)], { encoding: "utf8" })
    .stdout.split("\n")
    .map(Number)
    .filter(Boolean);
  children.forEach(killTree);
  try {
    process.kill(pid, "SIGKILL");
  } catch {
    // Already gone.
  }
}
