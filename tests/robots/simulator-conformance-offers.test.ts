// What a client offers on the simulated robot, through the real roslib client
// over real sockets, as rosbridge_suite does it (capabilities
// advertise_service, service_response, unadvertise_service; advertise with
// latch): a service a client advertises is called by another client through
// the bridge, and a latched topic gives a late subscriber its last message.
// The recorded transcripts have neither, so the expected frames come from
// rosbridge's own code: the relayed request is a call_service with the id
// "service_request:<name>:<n>" and the request's fields filled.
import * as ROSLIB from "roslib";
import { afterEach, describe, expect, it } from "vitest";
import { WebSocket } from "ws";
import { startSimulator, testServices, type Simulator } from "../../src/robots/simulator";

let sim: Simulator | null = null;
const open: ROSLIB.Ros[] = [];
afterEach(async () => {
  open.splice(0).forEach((ros) => ros.close());
  await sim?.close();
  sim = null;
});

async function client(url: string) {
  const ros = new ROSLIB.Ros({ url });
  await new Promise<void>((ok, fail) => {
    ros.on("connection", () => ok());
    ros.on("error", (e) => fail(new Error(`Could not reach the simulated robot at ${url}: ${String(e)}`)));
  });
  open.push(ros);
  return ros;
}

type SetBool = { data: boolean };
type Answer = { success: boolean; message: string };

/** A call through roslib: its values, or its failure text. */
function call(ros: ROSLIB.Ros, name: string, args: Record<string, unknown>, serviceType = "std_srvs/srv/SetBool") {
  return new Promise<{ ok: true; values: Answer } | { ok: false; error: string }>((resolve) =>
    new ROSLIB.Service<Record<string, unknown>, Answer>({ ros, name, serviceType }).callService(
      args,
      (values) => resolve({ ok: true, values }),
      (error) => resolve({ ok: false, error: String(error) }),
    ),
  );
}

/** The advertiser's side: every request it got, answered by `answer`. */
function advertise(ros: ROSLIB.Ros, name: string, answer: (request: SetBool, response: Partial<Answer>) => boolean) {
  const requests: SetBool[] = [];
  const service = new ROSLIB.Service<SetBool, Answer>({ ros, name, serviceType: "std_srvs/srv/SetBool" });
  void service.advertise((request, response) => {
    requests.push(request);
    return answer(request, response);
  });
  return { requests, service };
}

const advertised = (name: string) => expect.poll(() => sim!.graph.services.get(name)?.owner).toBeDefined();

describe("advertise_service from a client", () => {
  it("another client's call reaches the advertiser and its answer comes back", async () => {
    sim = await startSimulator({ port: 0, nodes: [] });
    const [robot, wizard] = [await client(sim.url), await client(sim.url)];
    const offered = advertise(robot, "/confirm", (request, response) => {
      Object.assign(response, { success: request.data, message: request.data ? "yes" : "no" });
      return true;
    });
    await advertised("/confirm");
    expect(await call(wizard, "/confirm", { data: true })).toEqual({
      ok: true,
      values: { success: true, message: "yes" },
    });
    // A field the caller left out is filled, as rosbridge sends the whole request.
    expect(await call(wizard, "/confirm", {})).toEqual({ ok: true, values: { success: false, message: "no" } });
    expect(offered.requests).toEqual([{ data: true }, { data: false }]);
  });

  it("the advertiser gets rosbridge's call_service frame, and a partial answer is filled with defaults", async () => {
    sim = await startSimulator({ port: 0, nodes: [] });
    const frames: Record<string, unknown>[] = [];
    const raw = new WebSocket(sim.url, { perMessageDeflate: false });
    raw.on("message", (data) => frames.push(JSON.parse(data.toString())));
    await new Promise((ok, fail) => raw.once("open", ok).once("error", fail));
    raw.send(JSON.stringify({ op: "advertise_service", type: "std_srvs/SetBool", service: "/confirm" }));
    await advertised("/confirm");
    const wizard = await client(sim.url);
    const answered = call(wizard, "confirm", { data: true });
    await expect.poll(() => frames.length).toBe(1);
    expect(frames[0]).toEqual({
      op: "call_service",
      id: "service_request:/confirm:1",
      service: "/confirm",
      args: { data: true },
    });
    raw.send(
      JSON.stringify({ op: "service_response", service: "/confirm", id: frames[0]!.id, values: {}, result: true }),
    );
    expect(await answered).toEqual({ ok: true, values: { success: false, message: "" } });
    raw.terminate();
  });

  it("calls in flight at once are answered each with its own response", async () => {
    sim = await startSimulator({ port: 0, nodes: [] });
    const robot = await client(sim.url);
    const held: Array<(values: Answer) => void> = [];
    const service = new ROSLIB.Service<SetBool, Answer>({ ros: robot, name: "/ask", serviceType: "std_srvs/SetBool" });
    void service.advertiseAsync(() => new Promise<Answer>((done) => held.push(done)));
    await advertised("/ask");
    const [first, second] = [await client(sim.url), await client(sim.url)];
    const answers = [call(first, "/ask", { data: true }), call(second, "/ask", { data: false })];
    await expect.poll(() => held.length).toBe(2);
    // Answered in the opposite order: each caller still gets its own.
    held[1]!({ success: false, message: "second" });
    held[0]!({ success: true, message: "first" });
    expect(await Promise.all(answers)).toEqual([
      { ok: true, values: { success: true, message: "first" } },
      { ok: true, values: { success: false, message: "second" } },
    ]);
  });

  it("an answer without values (roslib's callback returned false) answers nothing; the caller fails when the service goes", async () => {
    sim = await startSimulator({ port: 0, nodes: [] });
    const robot = await client(sim.url);
    const offered = advertise(robot, "/confirm", () => false);
    await advertised("/confirm");
    const wizard = await client(sim.url);
    const answer = call(wizard, "/confirm", { data: true });
    await expect.poll(() => sim!.log.some((l) => l.text.includes("missing values"))).toBe(true);
    await offered.service.unadvertise();
    const got = await answer;
    expect(got.ok).toBe(false);
    expect(got).toMatchObject({ error: expect.stringContaining("/confirm was unadvertised") });
    expect(sim.log.map((l) => l.text)).toContainEqual(
      expect.stringContaining("was unadvertised with a service call in progress"),
    );
  });

  it("a failure from roslib's advertiseAsync (values a string) answers nothing either, as rosbridge's type check refuses it", async () => {
    sim = await startSimulator({ port: 0, nodes: [] });
    const robot = await client(sim.url);
    const service = new ROSLIB.Service<SetBool, Answer>({ ros: robot, name: "/ask", serviceType: "std_srvs/SetBool" });
    void service.advertiseAsync(async () => {
      throw new Error("no motor");
    });
    await advertised("/ask");
    const answer = call(await client(sim.url), "/ask", { data: true });
    await expect.poll(() => sim!.log.some((l) => l.text === "service_response: values must be an object")).toBe(true);
    robot.close();
    expect(await answer).toMatchObject({ ok: false, error: expect.stringContaining("/ask was unadvertised") });
  });

  it("after unadvertise_service the service does not exist", async () => {
    sim = await startSimulator({ port: 0, nodes: [] });
    const [robot, wizard] = [await client(sim.url), await client(sim.url)];
    const offered = advertise(robot, "/confirm", () => true);
    await advertised("/confirm");
    await offered.service.unadvertise();
    await expect.poll(() => sim!.graph.services.has("/confirm")).toBe(false);
    const got = await call(wizard, "/confirm", { data: true });
    expect(got).toMatchObject({ ok: false, error: expect.stringContaining("does not exist") });
    expect(offered.requests).toEqual([]);
  });

  it("when the advertiser disconnects, its call in flight fails and the service is gone", async () => {
    sim = await startSimulator({ port: 0, nodes: [] });
    const [robot, wizard] = [await client(sim.url), await client(sim.url)];
    const service = new ROSLIB.Service<SetBool, Answer>({ ros: robot, name: "/ask", serviceType: "std_srvs/SetBool" });
    let asked = false;
    void service.advertiseAsync(() => {
      asked = true;
      return new Promise<Answer>(() => {});
    });
    await advertised("/ask");
    const pending = call(wizard, "/ask", { data: true });
    await expect.poll(() => asked).toBe(true);
    robot.close();
    expect(await pending).toMatchObject({ ok: false, error: expect.stringContaining("/ask was unadvertised") });
    expect(await call(wizard, "/ask", { data: true })).toMatchObject({
      ok: false,
      error: expect.stringContaining("does not exist"),
    });
  });

  it("a name already taken goes to the newest advertiser; the robot's own service is back when the client's ends", async () => {
    sim = await startSimulator({ port: 0, nodes: [testServices()] });
    const [first, second, wizard] = [await client(sim.url), await client(sim.url), await client(sim.url)];
    expect(await call(wizard, "/set_led", { data: true })).toEqual({
      ok: true,
      values: { success: true, message: "led=True" },
    });
    const one = advertise(first, "/set_led", (_, r) => Boolean(Object.assign(r, { success: true, message: "one" })));
    await expect.poll(() => sim!.graph.services.get("/set_led")?.owner).toBe("client:0");
    expect(await call(wizard, "/set_led", { data: true })).toEqual({
      ok: true,
      values: { success: true, message: "one" },
    });
    const two = advertise(second, "/set_led", (_, r) => Boolean(Object.assign(r, { success: true, message: "two" })));
    await expect.poll(() => sim!.graph.services.get("/set_led")?.owner).toBe("client:1");
    expect(sim.log.map((l) => l.text)).toContain("Duplicate service advertised. Overwriting /set_led.");
    expect(await call(wizard, "/set_led", { data: true })).toEqual({
      ok: true,
      values: { success: true, message: "two" },
    });
    expect([one.requests.length, two.requests.length]).toEqual([1, 1]);
    await two.service.unadvertise();
    await expect.poll(() => sim!.graph.services.get("/set_led")?.owner).toBeUndefined();
    expect(await call(wizard, "/set_led", { data: false })).toEqual({
      ok: true,
      values: { success: true, message: "led=False" },
    });
  });

  it("a service type the bridge does not know is refused (to the log) and nothing is offered", async () => {
    sim = await startSimulator({ port: 0, nodes: [] });
    const [robot, wizard] = [await client(sim.url), await client(sim.url)];
    void new ROSLIB.Service({ ros: robot, name: "/odd", serviceType: "no_such_srvs/Odd" }).advertise(() => true);
    await expect.poll(() => sim!.log.some((l) => l.text.startsWith("advertise_service:"))).toBe(true);
    expect(sim.log.find((l) => l.text.startsWith("advertise_service:"))?.text).toContain("no_such_srvs");
    expect(await call(wizard, "/odd", {})).toMatchObject({
      ok: false,
      error: expect.stringContaining("does not exist"),
    });
  });
});

describe("latch on advertise", () => {
  type Text = { data: string };
  const topic = (ros: ROSLIB.Ros, latch: boolean) =>
    new ROSLIB.Topic<Text>({ ros, name: "/greeting", messageType: "std_msgs/msg/String", latch });
  const published = (count: number) =>
    expect.poll(() => sim!.received.filter((r) => r.message.op === "publish").length).toBe(count);

  /** A late subscriber's messages, and a marker published after it subscribed. */
  async function lateSubscriber(publisher: ROSLIB.Topic<Text>) {
    const heard: string[] = [];
    const late = await client(sim!.url);
    topic(late, false).subscribe((m) => heard.push(m.data));
    await expect.poll(() => sim!.received.filter((r) => r.message.op === "subscribe").length).toBe(1);
    publisher.publish({ data: "after" });
    await expect.poll(() => heard.includes("after")).toBe(true);
    return heard;
  }

  it("a late subscriber gets the last message of a latched topic at once, then what follows", async () => {
    sim = await startSimulator({ port: 0, nodes: [] });
    const publisher = topic(await client(sim.url), true);
    publisher.publish({ data: "first" });
    publisher.publish({ data: "last" });
    await published(2);
    expect(sim.received.find((r) => r.message.op === "advertise")?.message.latch).toBe(true);
    expect(await lateSubscriber(publisher)).toEqual(["last", "after"]);
  });

  it("without latch a late subscriber gets nothing old", async () => {
    sim = await startSimulator({ port: 0, nodes: [] });
    const publisher = topic(await client(sim.url), false);
    publisher.publish({ data: "first" });
    publisher.publish({ data: "last" });
    await published(2);
    expect(await lateSubscriber(publisher)).toEqual(["after"]);
  });

  it("the latched message goes with its publisher: a subscriber after the advertiser left gets nothing old", async () => {
    sim = await startSimulator({ port: 0, nodes: [] });
    const gone = await client(sim.url);
    const publisher = topic(gone, true);
    publisher.publish({ data: "last" });
    await published(1);
    gone.close();
    await expect.poll(() => sim!.connections()).toBe(0);
    // Another client keeps the topic (unlatched) so a subscriber can see what comes next.
    const other = topic(await client(sim.url), false);
    other.advertise();
    await expect.poll(() => sim!.received.filter((r) => r.message.op === "advertise").length).toBe(2);
    expect(await lateSubscriber(other)).toEqual(["after"]);
  });
});
