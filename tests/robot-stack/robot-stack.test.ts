// The NAO6 bridge cannot run here (no Docker, no robot): check its files are
// well formed and consistent with each other and with the NAO6 plugin.
import { spawnSync } from "node:child_process";
import { readFileSync } from "node:fs";
import { join } from "node:path";
import { describe, expect, it } from "vitest";

const dir = join(import.meta.dirname, "..", "..", "robot-stack");
const read = (name: string) => readFileSync(join(dir, name), "utf8");
const variables = (text: string) => new Set([...text.matchAll(/\$\{(\w+)/g)].map((m) => m[1]!));

describe("robot-stack", () => {
  it("pins its base image and holds no secret", () => {
    const dockerfile = read("Dockerfile");
    expect(dockerfile).toMatch(/^FROM ros:humble-[\w-]+$/m);
    expect(dockerfile).not.toMatch(/PASSWORD=|password:/i);
  });

  it("lists in .env.example every variable the compose file and the entrypoint use", () => {
    const example = new Set(
      read(".env.example")
        .split("\n")
        .filter((l) => /^\w+=/.test(l))
        .map((l) => l.split("=")[0]!),
    );
    for (const name of [...variables(read("compose.yml")), ...variables(read("entrypoint.sh"))])
      expect(example).toContain(name);
  });

  it("has shell and Python files that parse", () => {
    expect(spawnSync("bash", ["-n", join(dir, "entrypoint.sh")]).status).toBe(0);
    for (const file of ["init_robot.py", "naoqi_node.py", "animation_relay.py", "word_relay.py"]) {
      const check = spawnSync(
        "python3",
        ["-c", "import ast,sys; ast.parse(open(sys.argv[1]).read())", join(dir, file)],
        { encoding: "utf8" },
      );
      expect(check.stderr).toBe("");
    }
  });

  it("relays every topic the NAO6 plugin publishes to", () => {
    const plugin = JSON.parse(readFileSync(join(dir, "..", "plugins", "nao6-ros2.json"), "utf8")) as {
      actions: Array<{ ros2?: { topic?: string } }>;
    };
    const topics = new Set(plugin.actions.map((a) => a.ros2?.topic).filter((t): t is string => !!t && t !== "/ssh"));
    const guide = readFileSync(join(dir, "..", "docs", "robot-setup.md"), "utf8");
    for (const topic of topics) expect(guide).toContain(`\`${topic}\``);
    expect(read("animation_relay.py")).toContain('"/animation"');
  });

  it("provides the topic of every event the NAO6 plugin senses that naoqi_driver does not publish", () => {
    const plugin = JSON.parse(readFileSync(join(dir, "..", "plugins", "nao6-ros2.json"), "utf8")) as {
      events: Array<{ topic: string; messageType: string }>;
    };
    // naoqi_driver2's own sensor topics (its README's list); every other event topic is a relay's.
    const byDriver = new Set(["/head_touch", "/hand_touch", "/bumper", "/sonar/left", "/sonar/right"]);
    const relays = read("animation_relay.py") + read("word_relay.py");
    const relayed = plugin.events.filter((e) => !byDriver.has(e.topic));
    expect(relayed.length).toBeGreaterThan(0);
    for (const event of relayed) {
      expect(relays).toContain(`"${event.topic}"`);
      expect(relays).toContain(`import ${event.messageType.split("/").pop()}`);
    }
  });

  it("binds the lab server's ports to loopback and takes its passwords from the environment", () => {
    const compose = readFileSync(join(dir, "..", "docker-compose.yml"), "utf8");
    const ports = [...compose.matchAll(/^\s+- "([^"]+)"$/gm)].map((m) => m[1]!).filter((p) => /:\d+$/.test(p));
    expect(ports.length).toBeGreaterThan(0);
    for (const port of ports) expect(port.startsWith("127.0.0.1:")).toBe(true);
    for (const line of compose.split("\n").filter((l) => /PASSWORD:/.test(l))) expect(line).toMatch(/\$\{\w+:\?/);
  });
});
