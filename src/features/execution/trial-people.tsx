// Who ran the trial (its wizard) and who created it: two people, often not
// the same, so two named fields on the trial page and in its analysis.
export function TrialPeople({
  wizardName,
  createdByName,
  started,
}: {
  wizardName: string | null;
  createdByName: string | null;
  /** Before the start, an unassigned trial's wizard is whoever starts it. */
  started: boolean;
}) {
  return (
    <dl className="flex flex-wrap gap-x-6 gap-y-1 text-sm" data-testid="trial-people">
      <div className="flex gap-1.5">
        <dt className="text-slate-600">Wizard:</dt>
        <dd className="font-medium">{wizardName ?? (started ? "not recorded" : "whoever starts it")}</dd>
      </div>
      <div className="flex gap-1.5">
        <dt className="text-slate-600">Created by:</dt>
        <dd className="font-medium">{createdByName ?? "not recorded"}</dd>
      </div>
    </dl>
  );
}
