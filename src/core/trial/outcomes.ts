// The words for what became of a robot action that was not done, said the
// same in the trial log, on the wizard's page, in the analysis and in the
// exports. Three different facts, never one "failed":
// - not sent: dropped before it left the runtime; the robot never got it;
// - sent, outcome unknown: it left for the robot and the link was lost before
//   an answer; it may still happen (a later report of the robot's is logged
//   against it), so asking again may do it twice;
// - failed: the robot or its transport said it failed.
export const OUTCOME_WORDS = {
  not_sent: "not sent",
  unknown: "sent, outcome unknown",
  failed: "failed",
} as const;

export type UndoneOutcome = keyof typeof OUTCOME_WORDS;
