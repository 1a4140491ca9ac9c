// The standard instruments as ready-made questionnaires, worded as published,
// so a study adds one with a click and it is scored the published way.
import type { Definition, Instrument } from "./definition";

const SUS_ITEMS = [
  "I think that I would like to use this system frequently.",
  "I found the system unnecessarily complex.",
  "I thought the system was easy to use.",
  "I think that I would need the support of a technical person to be able to use this system.",
  "I found the various functions in this system were well integrated.",
  "I thought there was too much inconsistency in this system.",
  "I would imagine that most people would learn to use this system very quickly.",
  "I found the system very cumbersome to use.",
  "I felt very confident using the system.",
  "I needed to learn a lot of things before I could get going with this system.",
];

// Godspeed (Bartneck et al., 2009), in the published order: anthropomorphism,
// animacy, likeability, perceived intelligence, perceived safety.
const GODSPEED_PAIRS: Array<[string, string]> = [
  ["Fake", "Natural"],
  ["Machinelike", "Humanlike"],
  ["Unconscious", "Conscious"],
  ["Artificial", "Lifelike"],
  ["Moving rigidly", "Moving elegantly"],
  ["Dead", "Alive"],
  ["Stagnant", "Lively"],
  ["Mechanical", "Organic"],
  ["Artificial", "Lifelike"],
  ["Inert", "Interactive"],
  ["Apathetic", "Responsive"],
  ["Dislike", "Like"],
  ["Unfriendly", "Friendly"],
  ["Unkind", "Kind"],
  ["Unpleasant", "Pleasant"],
  ["Awful", "Nice"],
  ["Incompetent", "Competent"],
  ["Ignorant", "Knowledgeable"],
  ["Irresponsible", "Responsible"],
  ["Unintelligent", "Intelligent"],
  ["Foolish", "Sensible"],
  ["Anxious", "Relaxed"],
  ["Agitated", "Calm"],
  ["Quiescent", "Surprised"],
];

export const INSTRUMENT_NAMES: Record<Instrument, string> = {
  sus: "System Usability Scale (SUS)",
  godspeed: "Godspeed questionnaire",
};

export function instrumentDefinition(instrument: Instrument): Definition {
  if (instrument === "sus") {
    return {
      title: INSTRUMENT_NAMES.sus,
      instructions: "For each statement, choose how much you agree, from 1 (strongly disagree) to 5 (strongly agree).",
      instrument,
      sections: [
        {
          id: "sus",
          title: "",
          randomize: false,
          items: SUS_ITEMS.map((text, i) => ({
            id: `sus${i + 1}`,
            kind: "likert",
            text,
            required: true,
            scale: { min: 1, max: 5, minLabel: "Strongly disagree", maxLabel: "Strongly agree" },
          })),
        },
      ],
    };
  }
  return {
    title: INSTRUMENT_NAMES.godspeed,
    instructions: "Please rate your impression of the robot on each of these scales.",
    instrument,
    sections: [
      {
        id: "godspeed",
        title: "",
        randomize: false,
        items: GODSPEED_PAIRS.map(([low, high], i) => ({
          id: `gs${i + 1}`,
          kind: "likert",
          text: `${low} – ${high}`,
          required: true,
          scale: { min: 1, max: 5, minLabel: low, maxLabel: high },
        })),
      },
    ],
  };
}
