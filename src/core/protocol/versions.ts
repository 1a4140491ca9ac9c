// Documents of every earlier format version, read as today's. Upgrades are
// numbered like database migrations: each reads one version and writes the
// next, and a document is walked up from its own version. A published
// snapshot keeps the bytes it was hashed with: it is upgraded as it is read,
// never written back, so its hash still verifies. An exchange file is
// upgraded once its shape is checked. Stored drafts are rows, upgraded by the
// database's migrations (src/store/migrations).
import { DOCUMENT_VERSION, type ProtocolSnapshot } from "./document";

type Stored = Record<string, unknown>;

/** Where a field sits in an exchange file. */
export type FilePlace = "experiment" | "step" | "action";

interface Upgrade {
  /** The version it writes; it reads the one before. */
  to: number;
  /** Fields an exchange file may carry from this version on: an older file that has one is not of its version. */
  fileFields: Partial<Record<FilePlace, string[]>>;
  snapshot(stored: Stored): Stored;
  file(stored: Stored): Stored;
}

// The next version's upgrade goes at the end, with DOCUMENT_VERSION bumped to its `to`.
const UPGRADES: Upgrade[] = [
  {
    to: 2,
    fileFields: { step: ["after"] },
    // Version 1 named the robot robotPluginId. Its steps had no "after": each
    // went on to the next, as a step without one still does, so steps are kept
    // as they are (and the snapshot's steps hash as they did).
    snapshot: ({ experiment, ...rest }) => {
      const { robotPluginId, ...fields } = experiment as Stored;
      return { ...rest, experiment: { ...fields, robotId: robotPluginId } };
    },
    file: (file) => file,
  },
  {
    to: 3,
    fileFields: { step: ["timeLimit"], action: ["timeLimit"] },
    // Version 2 had no time limits: a document without one is read as it was.
    snapshot: (snapshot) => snapshot,
    file: (file) => file,
  },
  {
    to: 4,
    fileFields: {},
    // Version 3 had no loops: every "after" it wrote reads as it was.
    snapshot: (snapshot) => snapshot,
    file: (file) => file,
  },
  {
    to: 5,
    fileFields: { step: ["variants"], action: ["variants"] },
    // Version 3 had no variants: every condition ran the one design, as a document without variants still does.
    snapshot: (snapshot) => snapshot,
    file: (file) => file,
  },
];

/** Every version this HRIStudio reads: 1 up to today's. */
export const READABLE_VERSIONS = Array.from({ length: DOCUMENT_VERSION }, (_, i) => i + 1);

/** A snapshot as stored (any version so far), in today's shape; the stored value is left as it is. */
export function readSnapshot(stored: unknown): ProtocolSnapshot {
  const version = (stored as { schemaVersion?: unknown } | null)?.schemaVersion;
  if (!READABLE_VERSIONS.includes(version as number))
    throw new Error(`Unknown experiment snapshot schema version ${String(version)}`);
  if (version === DOCUMENT_VERSION) return stored as ProtocolSnapshot;
  return upgraded(stored as Stored, version as number, "schemaVersion", (u) => u.snapshot) as ProtocolSnapshot;
}

/** An exchange file whose shape is checked (of a readable version), in today's shape. */
export function upgradeFile<File>(file: Stored): File {
  return upgraded(file, file.formatVersion as number, "formatVersion", (u) => u.file) as File;
}

/** The fields of `place` a file of `version` may not carry: those added by later versions. */
export function fieldsAfter(version: number, place: FilePlace): string[] {
  return UPGRADES.filter((u) => u.to > version).flatMap((u) => u.fileFields[place] ?? []);
}

function upgraded(stored: Stored, from: number, versionKey: string, step: (u: Upgrade) => Upgrade["file"]): Stored {
  return UPGRADES.filter((u) => u.to > from).reduce(
    (document, upgrade) => ({ ...step(upgrade)(document), [versionKey]: upgrade.to }),
    stored,
  );
}
