// What a study's status allows. Trials with participants run only while the
// study is active: a draft is still being prepared (its experiments can be
// rehearsed from the designer), and a completed or archived study keeps its
// data as it is.
export const STUDY_STATUSES = ["draft", "active", "completed", "archived"] as const;
export type StudyStatus = (typeof STUDY_STATUSES)[number];

/** What each status means, as the study's overview says it. */
export const STUDY_STATUS_HINT =
  "Draft studies can only rehearse; active studies run trials; completed and archived ones keep their data read-only.";

/** Why a study in this status may not run a new trial, or null when it may. */
export function trialRefusal(status: StudyStatus): string | null {
  switch (status) {
    case "active":
      return null;
    case "draft":
      return "This study is still a draft: rehearse its experiments from the designer, and set the study to active (Overview) before running trials with participants.";
    case "completed":
      return "This study is completed: its data is kept read-only and it runs no new trials. Set it back to active (Overview) to run more.";
    case "archived":
      return "This study is archived: its data is kept read-only and it runs no new trials.";
  }
}
