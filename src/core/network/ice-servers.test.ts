import { describe, expect, it } from "vitest";
import { parseIceServers } from "./ice-servers";

describe("HRI_ICE_SERVERS", () => {
  it.each([
    ["", { servers: [] }],
    ["  ", { servers: [] }],
    ["stun:stun.lab.org:3478", { servers: [{ urls: ["stun:stun.lab.org:3478"] }] }],
    ["stun:a.lab:3478, stun:b.lab:3478", { servers: [{ urls: ["stun:a.lab:3478"] }, { urls: ["stun:b.lab:3478"] }] }],
    [
      '[{"urls":"turn:turn.lab:3478","username":"lab","credential":"s3cret"}]',
      { servers: [{ urls: ["turn:turn.lab:3478"], username: "lab", credential: "s3cret" }] },
    ],
    [
      '[{"urls":["stun:a.lab","turns:t.lab:5349"],"username":"u","credential":"c"}]',
      { servers: [{ urls: ["stun:a.lab", "turns:t.lab:5349"], username: "u", credential: "c" }] },
    ],
  ])("reads %j", (setting, expected) => {
    expect(parseIceServers(setting)).toEqual(expected);
  });

  it.each([
    ["http://stun.lab.org", /"http:\/\/stun.lab.org" is not a stun: or turn: address/],
    ["[not json", /not valid JSON/],
    ['{"urls":"stun:a"}', /is not a stun: or turn: address/],
    ['[{"urls":[]}]', /server 1 needs "urls"/],
    ['[{"urls":"turn:t.lab"}]', /server 1 is a TURN server: give it a "username" and a "credential"/],
  ])("refuses %j, saying why", (setting, reason) => {
    const parsed = parseIceServers(setting);
    expect("error" in parsed && parsed.error).toMatch(reason);
  });
});
