// Which committed migrations a database has, read from what Drizzle's
// migrator records (the `when` of each migration it applied), and whether a
// backup at one level may be restored by this copy of HRIStudio.

export interface JournalEntry {
  tag: string;
  when: number;
}

export interface MigrationLevel {
  /** How many of the journal's migrations are applied; 0 = none. */
  level: number;
  /** The last one's name, e.g. "0005_isolation". */
  last: string | null;
}

/** The level of a database whose migrator recorded these times; refuses a migration this copy does not know. */
export function migrationLevel(journal: JournalEntry[], applied: number[]): MigrationLevel {
  if (!applied.length) return { level: 0, last: null };
  const latest = Math.max(...applied);
  const level = journal.filter((m) => m.when <= latest).length;
  if (journal[level - 1]?.when !== latest) {
    throw new Error(
      `The database has a migration this copy of HRIStudio does not know (applied as ${new Date(latest).toISOString()}). Run the backup with the HRIStudio version that runs this database.`,
    );
  }
  return { level, last: journal[level - 1]!.tag };
}

/** Refuses a restore this copy cannot do, in plain words; otherwise says nothing. */
export function checkRestoreLevels(journal: JournalEntry[], backup: MigrationLevel, target: MigrationLevel) {
  if (backup.level > journal.length) {
    throw new Error(
      `This backup comes from a newer HRIStudio (database migration ${backup.last}; this copy knows ${journal.length} migrations, up to ${journal.at(-1)?.tag}). Update HRIStudio, then restore.`,
    );
  }
  if (backup.level > 0 && journal[backup.level - 1]!.tag !== backup.last) {
    throw new Error(
      `This backup's database migration ${backup.last} is not this copy's migration ${backup.level} (${journal[backup.level - 1]!.tag}): it comes from another line of HRIStudio.`,
    );
  }
  if (target.level > backup.level) {
    throw new Error(
      `The target database is already set up at a later migration (${target.last}) than the backup (${backup.last ?? "none"}). Restore into a new, empty database or data folder.`,
    );
  }
}
