import { expect, it } from "vitest";
import { type EnrolledParticipant, enrolment, type RunTrial } from "./enrolment";

const experimentOf = new Map([
  ["a", "exp-a"],
  ["b", "exp-b"],
]);
const person = (id: string, conditionIds: string[], consentStatus: EnrolledParticipant["consentStatus"] = "given") => ({
  id,
  consentStatus,
  conditionIds,
});
const trial = (participantId: string, experimentId: string, status: RunTrial["status"]): RunTrial => ({
  id: `${participantId}-${experimentId}-${status}`,
  participantId,
  experimentId,
  status,
});
const none = (over: Partial<Record<"declined" | "stopped", number>> = {}) => [
  { reason: "declined consent", n: over.declined ?? 0 },
  { reason: "whose trial was stopped before its end", n: over.stopped ?? 0 },
];

it.each([
  { name: "no one yet", people: [], trials: [], counts: { enrolled: 0, completed: 0, withdrawn: 0, excluded: none() } },
  {
    name: "a completed trial counts in its condition only",
    people: [person("p1", ["a"]), person("p2", ["b"])],
    trials: [trial("p1", "exp-a", "completed")],
    counts: { enrolled: 1, completed: 1, withdrawn: 0, excluded: none() },
  },
  {
    name: "a withdrawn participant is counted as such, never as completed",
    people: [person("p1", ["a"], "withdrawn"), person("p2", ["a"])],
    trials: [trial("p1", "exp-a", "completed")],
    counts: { enrolled: 2, completed: 0, withdrawn: 1, excluded: none() },
  },
  {
    name: "declined consent, and a trial stopped before its end, are exclusions with their reasons",
    people: [person("p1", ["a"], "declined"), person("p2", ["a"]), person("p3", ["a"])],
    trials: [trial("p2", "exp-a", "aborted"), trial("p3", "exp-a", "aborted"), trial("p3", "exp-a", "completed")],
    counts: { enrolled: 3, completed: 1, withdrawn: 0, excluded: none({ declined: 1, stopped: 1 }) },
  },
  {
    name: "within subjects: a trial counts in the condition whose experiment it ran",
    people: [person("p1", ["b", "a"])],
    trials: [trial("p1", "exp-b", "completed")],
    counts: { enrolled: 1, completed: 0, withdrawn: 0, excluded: none() },
  },
])("$name", ({ people, trials, counts }) => {
  expect(enrolment("a", people, trials, experimentOf)).toEqual(counts);
});
