import { describe, expect, it } from "vitest";
import { pageCsp } from "./security-headers";

const directives = (csp: string) =>
  Object.fromEntries(csp.split("; ").map((d) => [d.split(" ")[0], d.split(" ").slice(1).join(" ")]));

describe("the pages' Content-Security-Policy", () => {
  it.each([
    ["ws://127.0.0.1:3001", "'self' ws://127.0.0.1:3001"],
    ["wss://lab.example.org/runtime", "'self' wss://lab.example.org"],
    ["ws://localhost:4001/", "'self' ws://localhost:4001"],
  ])("lets the page reach the trial runtime at %s", (runtimeUrl, connect) => {
    expect(directives(pageCsp(runtimeUrl))["connect-src"]).toBe(connect);
  });

  it("lets the robot page reach the simulated robot when there is one", () => {
    expect(directives(pageCsp("ws://127.0.0.1:3001", "ws://127.0.0.1:9090"))["connect-src"]).toBe(
      "'self' ws://127.0.0.1:3001 ws://127.0.0.1:9090",
    );
  });

  it("lets a page reach this site only when it names no runtime (someone not signed in)", () => {
    expect(directives(pageCsp())["connect-src"]).toBe("'self'");
  });

  it("forbids framing and plugins, allows blob: media and data: images, and scripts from this site only", () => {
    const csp = directives(pageCsp("ws://127.0.0.1:3001"));
    expect(csp).toMatchObject({
      "frame-ancestors": "'none'",
      "object-src": "'none'",
      "media-src": "'self' blob:",
      "img-src": "'self' blob: data:",
      "script-src": "'self' 'unsafe-inline' 'unsafe-eval'",
    });
  });
});
