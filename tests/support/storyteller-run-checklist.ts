// The "run" checklist of the project brief's protocol document (interactive-storyteller.md),
// scored by code from a trial's protocol version and event log.
import type { ProtocolSnapshot } from "../../src/core/protocol/snapshot";

interface Event {
  seq: number;
  type: string;
  relMs: number | null;
  actionId?: string;
  stepId?: string | null;
  actionType?: string;
  parameters?: Record<string, unknown>;
  optionId?: string;
  targetStepId?: string;
}

export const STORYTELLER_TEXT = {
  intro: "Hello. I want to tell you about Kai, an astronaut who went on a mission to Mars.",
  story:
    "Kai had been on the Martian surface for six days. On the seventh morning, she walked to the edge of a crater and looked down. Among the grey dust she saw a small rock that was bright red. She picked it up and carried it back to the base.",
  question: "What color was the rock Kai found?",
  correct: "That's right, the rock was red. Thank you for listening!",
  incorrect: "Actually, the rock was red. Thank you for listening!",
};

export function scoreRun(protocol: ProtocolSnapshot, events: Event[]) {
  const actions = protocol.steps.flatMap((s) => s.actions.map((a) => ({ ...a, stepId: s.id })));
  const byText = (text: string) => actions.find((a) => a.type === "say" && a.parameters.text === text);
  const first = (type: string, actionId: string | undefined) =>
    events.find((e) => e.type === type && e.actionId === actionId);
  const delivered = (text: string) => {
    const design = byText(text);
    const requested = first("action.requested", design?.id);
    return !!requested && requested.parameters?.text === text && !!first("action.completed", design?.id);
  };
  const partnerOf = (speech: ReturnType<typeof byText>, types: string[]) =>
    actions.find(
      (a) =>
        a.stepId === speech?.stepId &&
        types.includes(a.type) &&
        a.parallelGroup &&
        a.parallelGroup === speech?.parallelGroup,
    );
  const ranOnRobot = (actionId: string | undefined) =>
    !!first("action.dispatched", actionId) && !!first("action.completed", actionId);
  const startedWithin = (a: string | undefined, b: string | undefined, ms: number) => {
    const x = first("action.requested", a)?.relMs;
    const y = first("action.requested", b)?.relMs;
    return x != null && y != null && Math.abs(x - y) <= ms;
  };

  const answer = events.find((e) => e.type === "answer.recorded");
  const responseText = answer?.optionId === "correct" ? STORYTELLER_TEXT.correct : STORYTELLER_TEXT.incorrect;
  const branch = events.find((e) => e.type === "branch.resolved");
  const response = byText(responseText);
  const wave = partnerOf(byText(STORYTELLER_TEXT.intro), ["wave"]);
  const narrative = partnerOf(byText(STORYTELLER_TEXT.story), ["look_down", "pause"]);
  const reaction = partnerOf(response, ["nod", "head_shake"]);
  const pause = actions.find((a) => a.type === "pause" && a.stepId === byText(STORYTELLER_TEXT.question)?.stepId);
  const held =
    (first("action.completed", pause?.id)?.relMs ?? 0) - (first("action.dispatched", pause?.id)?.relMs ?? Infinity);
  const asked = first("action.requested", byText(STORYTELLER_TEXT.question)?.id)?.relMs ?? -1;

  const items: Array<[string, boolean]> = [
    ["intro speech delivered as designed", delivered(STORYTELLER_TEXT.intro)],
    ["story speech delivered as designed", delivered(STORYTELLER_TEXT.story)],
    ["question delivered as designed", delivered(STORYTELLER_TEXT.question)],
    [
      "the response matching the recorded answer",
      !!answer && branch?.targetStepId === response?.stepId && delivered(responseText),
    ],
    ["wave as its own robot command", ranOnRobot(wave?.id)],
    ["narrative gesture as its own robot command", ranOnRobot(narrative?.id)],
    [
      "nod or head shake as its own robot command",
      ranOnRobot(reaction?.id) && (reaction?.type === "nod") === (answer?.optionId === "correct"),
    ],
    [
      "gestures started within 500 ms of their speech",
      startedWithin(wave?.id, byText(STORYTELLER_TEXT.intro)?.id, 500) &&
        startedWithin(narrative?.id, byText(STORYTELLER_TEXT.story)?.id, 500) &&
        startedWithin(reaction?.id, response?.id, 500),
    ],
    [
      "the pause held for its designed length before the question",
      held >= Number(pause?.parameters.seconds ?? Infinity) * 1000 &&
        asked >= (first("action.completed", pause?.id)?.relMs ?? Infinity),
    ],
    [
      "no disconnection, crash or hang",
      events.some((e) => e.type === "trial.completed") &&
        !events.some((e) =>
          ["action.failed", "action.timed_out", "trial.aborted", "trial.emergency_stop"].includes(e.type),
        ),
    ],
  ];
  return {
    score: items.filter(([, ok]) => ok).length * 10,
    failed: items.filter(([, ok]) => !ok).map(([name]) => name),
  };
}
