// The SSH transport against a real sshd on loopback, with a recording qicli:
// every NAO6 SSH action arrives as exactly its argv, and no parameter can
// reach the shell.
import { existsSync, readFileSync } from "node:fs";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { loadPlugin, type Plugin, type PluginAction } from "../../src/core/plugins";
import { SshTransport } from "../../src/robots/transports/ssh";
import { startSshd, type TestSshd } from "../support/sshd";

const nao = (loadPlugin("nao6-ros2.json", readFileSync("plugins/nao6-ros2.json", "utf8")) as { value: Plugin }).value;
const sshActions = nao.actions.filter(
  (a) => a.ros2 && "payloadMapping" in a.ros2 && a.ros2.payloadMapping?.type === "ssh",
);

function command(id: string, sshCommand: string, extra: Partial<PluginAction> = {}): PluginAction {
  return {
    id,
    name: id,
    category: "test",
    parameterSchema: { type: "object", properties: { text: { type: "string" } } },
    ros2: { topic: "/ssh", messageType: "std_msgs/msg/String", payloadMapping: { type: "ssh", sshCommand } },
    ...extra,
  } as PluginAction;
}

describe.sequential("the SSH transport", () => {
  let sshd: TestSshd;
  let transport: SshTransport;
  beforeAll(async () => {
    sshd = await startSshd();
    transport = new SshTransport({
      host: "127.0.0.1",
      port: sshd.port,
      username: sshd.username,
      privateKeyFile: sshd.keyFile,
    });
    await transport.connect();
  });
  afterAll(async () => {
    await transport?.close();
    sshd?.stop();
  });

  it("runs every SSH action of the NAO6 plugin as its exact qicli command", async () => {
    expect(sshActions.map((a) => a.id)).toEqual(["wake_up", "rest", "stand", "stand_init", "sit", "crouch"]);
    for (const action of sshActions)
      expect(await transport.dispatch(action, {})).toEqual({
        status: "completed",
        detail: { exitCode: 0, confirmation: { by: "command_exit", confirmed: true } },
      });
    const expected = sshActions.map((a) =>
      (a.ros2 as { payloadMapping: { sshCommand: string } }).payloadMapping.sshCommand.split(" ").slice(1),
    );
    expect(sshd.calls()).toEqual(expected);
  });

  it("passes hostile text as one argument and runs nothing of it", async () => {
    const marker = `/tmp/hri-pwned-${process.pid}`;
    const text = `'; touch ${marker}; echo '$(touch ${marker})\`touch ${marker}\` && {{text}} "quoted" \\ \n new line 🪨`;
    const before = sshd.calls().length;
    expect(
      await transport.dispatch(command("say_over_ssh", "qicli call ALTextToSpeech.say {{text}}"), { text }),
    ).toMatchObject({ status: "completed" });
    expect(sshd.calls().slice(before)).toEqual([["call", "ALTextToSpeech.say", text]]);
    expect(existsSync(marker)).toBe(false);
  });

  it("reports the robot's refusal with its own words", async () => {
    expect(await transport.dispatch(command("broken", "qicli call fail"), {})).toEqual({
      status: "failed",
      reason: "the robot refused the command (exit 2): ALMotion: motors are off",
    });
  });

  it("times out an action that does not answer within the plugin's timeout", async () => {
    expect(await transport.dispatch(command("slow", "qicli call slow", { timeout: 300 }), {})).toMatchObject({
      status: "timed_out",
    });
  });

  it("refuses parameters the action does not declare, before reaching the robot", async () => {
    const before = sshd.calls().length;
    const outcome = await transport.dispatch(command("say_over_ssh", "qicli call ALTextToSpeech.say {{text}}"), {
      text: "hi",
      colour: "red",
    });
    expect(outcome.status).toBe("failed");
    expect(sshd.calls().length).toBe(before);
  });

  it("reports a dropped connection at once", async () => {
    const states: string[] = [];
    transport.onHealth((h) => states.push(h.state));
    sshd.stop();
    await expect.poll(() => states.includes("disconnected"), { timeout: 8000 }).toBe(true);
  });
});
