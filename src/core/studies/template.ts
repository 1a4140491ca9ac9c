// A new study's settings when it starts from another study: what is design
// is carried over, what belongs to the source's own run is not. One decision
// per setting, made here in the type, so a setting added later cannot be
// carried (or dropped) without someone deciding which it is.
import { studySettingsSchema, type StudySettings } from "./settings";

type Decisions = {
  [K in keyof StudySettings]: (
    source: StudySettings[K],
    fresh: StudySettings[K],
    newSeed: () => string,
  ) => StudySettings[K];
};

const DECISIONS: Decisions = {
  // The ethics rule of the protocol: trials need recorded consent. Design.
  requireConsent: (source) => source,
  // The strategy and its block size are the design of the study; the seed is
  // the source's own sequence, and reusing it would hand the new study the
  // same, already known, order of conditions: a new one is made, as for any
  // change of strategy.
  assignment: (source, _fresh, newSeed) => ({ ...source, seed: newSeed() }),
  // Who is blind to what is part of the method, decided before any trial.
  blinding: (source) => ({ ...source }),
  // The questions asked of each participant are design; the answers stay
  // with the source's participants, which are never copied.
  demographics: (source) => source.map((field) => ({ ...field, options: [...field.options] })),
  // The consent document is approved for one study: the new study's starts
  // again at the first version, and its researchers set their own.
  consentDocumentVersion: (_source, fresh) => fresh,
  // The checkbox's words and the name participants see are part of the method, like the blinds.
  consentAgreement: (source) => source,
  neutralTitle: (source) => source,
};

export function templateSettings(source: StudySettings, newSeed: () => string): StudySettings {
  const fresh = studySettingsSchema.parse({});
  const decide = <K extends keyof StudySettings>(key: K) =>
    (DECISIONS[key] as (s: StudySettings[K], f: StudySettings[K], n: () => string) => StudySettings[K])(
      source[key],
      fresh[key],
      newSeed,
    );
  return Object.fromEntries(
    (Object.keys(DECISIONS) as Array<keyof StudySettings>).map((key) => [key, decide(key)]),
  ) as StudySettings;
}
