import { describe, expect, it } from "vitest";
import { parseSecretReference, robotSecretNames } from "./secrets";

describe("secret references", () => {
  it.each([
    ["env:HRI_ROBOT_SECRET_NAO_A", { kind: "env", name: "HRI_ROBOT_SECRET_NAO_A" }],
    ["env:HRI_ROBOT_SECRET_SIMULATED_ROBOT_1", { kind: "env", name: "HRI_ROBOT_SECRET_SIMULATED_ROBOT_1" }],
    // The environment's robot, as a deployment named it before records.
    ["env:HRI_ROBOT_SSH_PASSWORD", { kind: "env", name: "HRI_ROBOT_SSH_PASSWORD" }],
    ["file:/etc/hristudio/nao-a.key", { kind: "file", path: "/etc/hristudio/nao-a.key" }],
    ["file:/c:/odd:name", { kind: "file", path: "/c:/odd:name" }],
  ])("%s is read as a reference", (reference, expected) => {
    expect(parseSecretReference(reference)).toEqual(expected);
  });

  const notRobots = (name: string) =>
    `refers to ${name}, which is not a robot secret; name a variable starting HRI_ROBOT_SECRET_`;
  it.each([
    ["a plain password", "hunter2", "must be env:VARIABLE or file:/path"],
    ["a password after env:", "env:p@ss word", "must name an environment variable, e.g. env:HRI_ROBOT_SECRET_NAO_A"],
    ["a relative key path", "file:keys/nao.key", "absolute path"],
    ["nothing after the kind", "env:", "must name an environment variable"],
    ["the platform's signing secret", "env:BETTER_AUTH_SECRET", notRobots("BETTER_AUTH_SECRET")],
    ["the database's address and password", "env:DATABASE_URL", notRobots("DATABASE_URL")],
    ["the media store's address", "env:HRI_MEDIA_S3_URL", notRobots("HRI_MEDIA_S3_URL")],
    ["a robot variable of another name", "env:NAO_A_SSH_PASSWORD", notRobots("NAO_A_SSH_PASSWORD")],
    ["the prefix alone", "env:HRI_ROBOT_SECRET_", notRobots("HRI_ROBOT_SECRET_")],
    ["the prefix in another case", "env:hri_robot_secret_nao", notRobots("hri_robot_secret_nao")],
    ["the prefix inside another name", "env:X_HRI_ROBOT_SECRET_NAO", notRobots("X_HRI_ROBOT_SECRET_NAO")],
  ])("%s is refused", (_, reference, reason) => {
    const parsed = parseSecretReference(reference);
    expect("error" in parsed && parsed.error).toContain(reason);
  });
});

it("offers the robot variables by name, and no other", () => {
  expect(
    robotSecretNames([
      "PATH",
      "HRI_ROBOT_SECRET_PEPPER",
      "BETTER_AUTH_SECRET",
      "HRI_ROBOT_SSH_PASSWORD",
      "HRI_ROBOT_SECRET_NAO_A",
      "DATABASE_URL",
      "HRI_ROBOT_SSH_HOST",
    ]),
  ).toEqual(["HRI_ROBOT_SECRET_NAO_A", "HRI_ROBOT_SECRET_PEPPER"]);
});
