// The silent-topic report through the real rosbridge transport (roslib over a
// real socket), against a server that answers each subscribe as the recorded
// ROS 1 rosbridge did (transcripts 03 and 06 with 06's server log): a
// subscription it took gets its recorded frames at their recorded spacing; one
// it refused gets nothing at all, as on the wire. No recorded frame shows a
// refusal (the server sends no status frames, README G1), so the status-frame
// case builds one in rosbridge's protocol shape from the recorded log line's
// own words: our construction, noted in the transcripts' README.
import { readFileSync } from "node:fs";
import type { AddressInfo } from "node:net";
import { afterEach, describe, expect, it } from "vitest";
import { type WebSocket, WebSocketServer } from "ws";
import { loadPlugin, type Plugin } from "../../src/core/plugins";
import { RosbridgeTransport } from "../../src/robots/transports/rosbridge";
import { readTranscript, TRANSCRIPTS, type Line } from "./support/replay";

const nao = (loadPlugin("nao6-ros2.json", readFileSync("plugins/nao6-ros2.json", "utf8")) as { value: Plugin }).value;
const say = nao.actions.find((a) => a.id === "say_text")!;

type Frame = { op?: string; id?: string; topic?: string; type?: string };
const recordings = ["03-subscribe-throttle-unsubscribe", "06-publish-type-errors"].map((name) => ({
  lines: readTranscript(`${name}.jsonl`),
  log: readFileSync(`${TRANSCRIPTS}/server-logs/${name}.log`, "utf8").split("\n"),
}));

/**
 * What the recorded server did with the last subscribe of this topic and type (03's last is unthrottled):
 * refused it (its log's words) or sent these frames.
 */
function recorded(topic: string, type: string): { refused: string } | { frames: Line[] } | null {
  for (const { lines, log } of recordings) {
    const at = lines.findLastIndex((l) => {
      const f = l.frame as Frame;
      return l.dir === "send" && f.op === "subscribe" && f.topic === topic && f.type === type;
    });
    if (at < 0) continue;
    const id = (lines[at]!.frame as Frame).id;
    const refused = log.find((line) => line.includes(`[id: ${id}] subscribe: `));
    if (refused) return { refused: refused.slice(refused.indexOf("subscribe: ")) };
    // What came on the topic until the client's next frame.
    const next = lines.findIndex((l, i) => i > at && l.dir === "send");
    const frames = lines.slice(at + 1, next).filter((l) => l.dir === "recv" && (l.frame as Frame).topic === topic);
    return { frames };
  }
  return null;
}

let server: WebSocketServer | null = null;
let transports: RosbridgeTransport[] = [];
afterEach(async () => {
  await Promise.all(transports.map((t) => t.close()));
  await new Promise((resolve) => server?.close(resolve) ?? resolve(null));
  transports = [];
  server = null;
});

/** The recorded bridge; `statusFrames`: also say a refusal, in rosbridge's `status` shape. */
async function bridge(statusFrames = false) {
  const sent: unknown[] = [];
  const timers = new Set<NodeJS.Timeout>();
  server = new WebSocketServer({ port: 0, host: "127.0.0.1" });
  await new Promise((resolve) => server!.once("listening", resolve));
  server.on("close", () => timers.forEach(clearTimeout));
  const send = (socket: WebSocket, frame: unknown) => {
    sent.push(frame);
    socket.send(JSON.stringify(frame));
  };
  server.on("connection", (socket) =>
    socket.on("message", (data) => {
      const m = JSON.parse(String(data)) as Frame;
      if (m.op !== "subscribe") return;
      const answer = recorded(m.topic!, m.type!);
      if (!answer) return;
      if ("refused" in answer) {
        if (statusFrames) send(socket, { op: "status", level: "error", id: m.id, msg: answer.refused });
        return;
      }
      // The recorded frames again and again, each after its recorded gap.
      const play = (i: number) => {
        const line = answer.frames[i % answer.frames.length]!;
        const gap = i === 0 ? 0 : Math.max(0, line.t_ms - answer.frames[(i - 1) % answer.frames.length]!.t_ms);
        const timer = setTimeout(() => {
          timers.delete(timer);
          if (socket.readyState !== socket.OPEN) return;
          send(socket, line.frame);
          play(i + 1);
        }, gap);
        timers.add(timer);
      };
      if (answer.frames.length) play(0);
    }),
  );
  return { url: `ws://127.0.0.1:${(server.address() as AddressInfo).port}`, sent };
}

async function connect(url: string, silentFloorMs: number) {
  const transport = new RosbridgeTransport({ url, silentFloorMs });
  transports.push(transport);
  const problems: string[] = [];
  transport.onHealth((h) => h.problem && problems.push(h.problem));
  await transport.connect();
  return { transport, problems };
}

describe("silent topics, against the recorded ROS 1 rosbridge", () => {
  it("a state topic under its ROS 2 type name: nothing on the wire, the silence told with the usual cause; under its ROS 1 name it flows (03) and nothing is told", async () => {
    const { url, sent } = await bridge();
    const ros2 = await connect(url, 1000);
    ros2.transport.subscribe("/joint_states", "sensor_msgs/msg/JointState", () => {}, { throttleRate: 100 });
    const ros1 = await connect(url, 1000);
    const joints: unknown[] = [];
    ros1.transport.subscribe("/joint_states", "sensor_msgs/JointState", (m) => joints.push(m), { throttleRate: 100 });
    await expect.poll(() => ros2.problems, { timeout: 10_000 }).toHaveLength(1);
    expect(ros2.problems).toEqual([
      "The robot never sent /joint_states (expected about every 0.1 s; nothing in 1 s): the usual causes are a ROS 1 bridge, which refuses the ROS 2 type name sensor_msgs/msg/JointState without telling us (it names it sensor_msgs/JointState), or nothing on the robot publishing /joint_states.",
    ]);
    expect(ros2.transport.health().state).toBe("connected");
    // Twenty messages at the recorded 10 Hz span two silence windows of 1 s.
    await expect.poll(() => joints.length, { timeout: 10_000 }).toBeGreaterThanOrEqual(20);
    expect(ros1.problems).toEqual([]);
    expect(sent.every((f) => (f as { op?: string }).op === "publish")).toBe(true);
  });

  it("a bridge that says what it refused: told at once, in the recorded log's words", async () => {
    const { url, sent } = await bridge(true);
    // A floor far beyond the test: only the refusal can tell it.
    const { transport, problems } = await connect(url, 600_000);
    transport.subscribe("/joint_states", "sensor_msgs/msg/JointState", () => {}, { throttleRate: 100 });
    await expect.poll(() => problems).toHaveLength(1);
    expect(sent).toEqual([
      {
        op: "status",
        level: "error",
        id: expect.stringMatching(/^subscribe:\/joint_states:/),
        msg: "subscribe: sensor_msgs/msg/JointState is not a valid type string",
      },
    ]);
    expect(problems).toEqual([
      "The robot never sent /joint_states (expected about every 0.1 s): the bridge refused its type sensor_msgs/msg/JointState — a ROS 1 bridge names it sensor_msgs/JointState.",
    ]);
  });

  it("a say whose done topic has a ROS 2 type name times out, and the wizard is told why", async () => {
    const { url } = await bridge();
    const { transport, problems } = await connect(url, 600_000);
    expect(await transport.dispatch({ ...say, timeout: 300 }, { text: "hi" })).toMatchObject({ status: "timed_out" });
    expect(problems).toEqual([
      "The robot never sent /speech_done (expected after each action that waits for it; an action waited for it until its timeout): the usual causes are a ROS 1 bridge, which refuses the ROS 2 type name std_msgs/msg/String without telling us (it names it std_msgs/String), or nothing on the robot publishing /speech_done.",
    ]);
  });
});
