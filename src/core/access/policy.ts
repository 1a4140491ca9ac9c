// The one access policy: (system role, study role, operation) → decision.
// Pure; the tRPC middleware and the trial runtime both ask it.

export const SYSTEM_ROLES = ["administrator", "researcher", "wizard", "observer"] as const;
export const STUDY_ROLES = ["owner", "researcher", "wizard", "observer"] as const;
export type SystemRole = (typeof SYSTEM_ROLES)[number];
export type StudyRole = (typeof STUDY_ROLES)[number];

/** Operations that need no study: who may do them depends on the system role. */
export const SYSTEM_OPERATIONS = {
  "account.read": ["administrator", "researcher", "wizard", "observer"],
  "study.create": ["administrator", "researcher"],
  "plugin.read": ["administrator", "researcher", "wizard", "observer"],
  "admin.users": ["administrator"],
  "admin.plugins": ["administrator"],
  "admin.robots": ["administrator"],
  // Anyone may hold access tokens; each reaches only studies whose data its owner may read.
  "token.manage": ["administrator", "researcher", "wizard", "observer"],
  // The studies whose data I may read: the analysis API's list.
  "data.studies": ["administrator", "researcher", "wizard", "observer"],
} as const satisfies Record<string, readonly SystemRole[]>;

/** Operations on one study: who may do them depends on the role in that study. */
export const STUDY_OPERATIONS = {
  "study.read": ["owner", "researcher", "wizard", "observer"],
  "study.update": ["owner"],
  "study.delete": ["owner"],
  "member.read": ["owner", "researcher", "wizard", "observer"],
  "member.manage": ["owner"],
  "experiment.read": ["owner", "researcher", "wizard", "observer"],
  "experiment.edit": ["owner", "researcher"],
  "version.publish": ["owner", "researcher"],
  "participant.read": ["owner", "researcher", "wizard", "observer"],
  "participant.manage": ["owner", "researcher"],
  // Undoing a withdrawal is the owner's alone, and always on the record.
  "participant.reinstate": ["owner"],
  "trial.read": ["owner", "researcher", "wizard", "observer"],
  "trial.create": ["owner", "researcher", "wizard"],
  "trial.run": ["owner", "researcher", "wizard"],
  "annotation.create": ["owner", "researcher", "wizard", "observer"],
  "data.read": ["owner", "researcher", "observer"],
  // A trial's recording, to code it afterwards: it shows the trial, never its condition's name, so a condition blind lets it through.
  "recording.read": ["owner", "researcher", "observer"],
} as const satisfies Record<string, readonly StudyRole[]>;

export type SystemOperation = keyof typeof SYSTEM_OPERATIONS;
export type StudyOperation = keyof typeof STUDY_OPERATIONS;
export type Operation = SystemOperation | StudyOperation;

/**
 * All a personal access token may do: list and read analysis data. No
 * writes, no token management, nothing a signed-in page needs.
 */
export const TOKEN_OPERATIONS: readonly Operation[] = ["data.studies", "data.read", "recording.read"];

export type Decision =
  | { allow: true }
  // `hidden`: the caller may not even learn that the study exists.
  | { allow: false; hidden: boolean; reason: string };

export interface Subject {
  systemRole: SystemRole;
  /** The caller's role in the study the operation concerns; null if not a member. */
  studyRole: StudyRole | null;
  /** What the study's blinds hide from this caller (none when absent). */
  blinding?: { conditionsHidden: boolean; resultsHidden: boolean };
  /** The caller came with a personal access token: read-only, on top of everything else. */
  viaToken?: boolean;
}

export function isStudyOperation(op: Operation): op is StudyOperation {
  return op in STUDY_OPERATIONS;
}

export function decide(subject: Subject, op: Operation): Decision {
  if (subject.viaToken && !TOKEN_OPERATIONS.includes(op))
    return { allow: false, hidden: false, reason: "An access token may only read analysis data." };
  if (!isStudyOperation(op)) {
    const allowed: readonly SystemRole[] = SYSTEM_OPERATIONS[op];
    return allowed.includes(subject.systemRole)
      ? { allow: true }
      : { allow: false, hidden: false, reason: `Your account (${subject.systemRole}) may not do this.` };
  }
  // Study data belongs to its members only, administrators included.
  if (subject.studyRole === null) {
    return { allow: false, hidden: true, reason: "Study not found." };
  }
  // Experiments, versions and conditions name the condition; a blinded wizard runs sessions without them.
  if (op === "experiment.read" && subject.blinding?.conditionsHidden) {
    return {
      allow: false,
      hidden: false,
      reason:
        subject.studyRole === "observer"
          ? "This study hides its conditions from observers (blinding): observe and code from the trial's page."
          : "This study hides its conditions from wizards (blinding): run your sessions from “My sessions”.",
    };
  }
  // Results, exports and the analysis pages name each trial's condition: a condition-blind observer waits for the blind to lift.
  if (op === "data.read" && subject.blinding?.conditionsHidden) {
    return {
      allow: false,
      hidden: false,
      reason: "This study hides its conditions from observers (blinding): results and exports open when it is lifted.",
    };
  }
  if ((op === "data.read" || op === "recording.read") && subject.blinding?.resultsHidden) {
    return { allow: false, hidden: false, reason: "This study hides results until it is marked completed (blinding)." };
  }
  return studyRoleMay(subject.studyRole, op)
    ? { allow: true }
    : {
        allow: false,
        hidden: false,
        reason: `As ${article(subject.studyRole)} ${subject.studyRole} of this study you may not do this.`,
      };
}

/** What the interface asks to decide which controls to offer; the server decides again. */
export function studyRoleMay(role: StudyRole, op: StudyOperation): boolean {
  return (STUDY_OPERATIONS[op] as readonly StudyRole[]).includes(role);
}

/**
 * Whether someone who may run trials runs this one (or this session): owners and researchers run any,
 * a wizard those assigned to them or to nobody (starting an unassigned one makes it theirs).
 */
export function runsAssigned(role: StudyRole, assignedWizardId: string | null, userId: string): boolean {
  return role !== "wizard" || assignedWizardId === null || assignedWizardId === userId;
}

function article(word: string) {
  return /^[aeiou]/.test(word) ? "an" : "a";
}
