import { describe, expect, it } from "vitest";
import { readBody, withinLimit } from "./body-limit";

const streamed = (...parts: number[]) =>
  new ReadableStream<Uint8Array>({
    start(controller) {
      for (const n of parts) controller.enqueue(new Uint8Array(n).fill(1));
      controller.close();
    },
  });
const request = (body: BodyInit | null, headers: Record<string, string> = {}) =>
  new Request("http://test/x", { method: "POST", body, headers, duplex: "half" } as RequestInit);

describe("reading a body with a limit of 10 bytes", () => {
  it.each([
    ["an empty body", null, {}, 0],
    ["exactly the limit, in pieces", streamed(4, 6), {}, 10],
    ["under the limit, declared", new Uint8Array(7), { "content-length": "7" }, 7],
  ])("gives back %s", async (_name, body, headers, length) => {
    const bytes = await readBody(request(body, headers), 10, "A test body");
    expect(bytes).toBeInstanceOf(Uint8Array);
    expect((bytes as Uint8Array).length).toBe(length);
  });

  it.each([
    ["one byte over, in pieces", streamed(5, 6), {}, "A test body may be at most 10 bytes; this one is larger."],
    [
      "declared over",
      streamed(1),
      { "content-length": "2048" },
      "A test body may be at most 10 bytes; this one is 2 KB.",
    ],
  ])("refuses %s with 413", async (_name, body, headers, message) => {
    const res = (await readBody(request(body, headers), 10, "A test body")) as Response;
    expect([res.status, await res.text()]).toEqual([413, message]);
  });

  it("hands a route a copy it can read, with its length and no chunked encoding", async () => {
    const copy = (await withinLimit(
      request(streamed(3, 3), { "transfer-encoding": "chunked", "x-kept": "yes" }),
      10,
      "A test body",
    )) as Request;
    expect(copy.headers.get("content-length")).toBe("6");
    expect(copy.headers.get("transfer-encoding")).toBeNull();
    expect(copy.headers.get("x-kept")).toBe("yes");
    expect((await copy.arrayBuffer()).byteLength).toBe(6);
  });
});
