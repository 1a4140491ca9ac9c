"use client";
import { useMutation, useQueryClient } from "@tanstack/react-query";
import { useState, type FormEvent } from "react";
import type { StudyRole } from "@/core/access/policy";
import { studyRoleMay } from "@/core/access/policy";
import { useTRPC } from "@/lib/trpc";
import { Button } from "@/ui/button";
import { Field, Input, NativeSelect, Textarea } from "@/ui/field";
import { fieldError, Problem } from "@/ui/problem";
import { Card } from "@/ui/surface";
import type { StudySettings } from "@/core/studies/settings";
import { STUDY_STATUS_HINT, STUDY_STATUSES, type StudyStatus } from "@/core/studies/status";
import { DeleteStudy } from "./delete-study";
import { DemographicsEditor } from "./demographics-editor";

type Study = {
  id: string;
  title: string;
  description: string;
  status: StudyStatus;
  settings: StudySettings;
  myRole: StudyRole;
};

/** Each blind a study may set, as the researcher reads it. */
const BLINDS: Array<{ key: keyof StudySettings["blinding"]; label: string; hint: string }> = [
  {
    key: "conditionsFromWizards",
    label: "Hide each session's condition from wizards",
    hint: "Wizards run sessions from “My sessions” and never see condition or experiment names.",
  },
  {
    key: "conditionsFromObservers",
    label: "Hide each session's condition from observers",
    hint: "Observers code live without condition or experiment names; results and exports, which name conditions, open to them when this is lifted.",
  },
  {
    key: "resultsUntilComplete",
    label: "Hide results from researchers and observers until the study is completed",
    hint: "Analysis and exports open when the status is set to completed. Lifting a blind is logged.",
  },
];

export function OverviewTab({ study }: { study: Study }) {
  const trpc = useTRPC();
  const queryClient = useQueryClient();
  const editable = studyRoleMay(study.myRole, "study.update");
  const [title, setTitle] = useState(study.title);
  const [description, setDescription] = useState(study.description);
  const [status, setStatus] = useState(study.status);
  const [requireConsent, setRequireConsent] = useState(study.settings.requireConsent);
  const [blinding, setBlinding] = useState(study.settings.blinding);
  const [consentDocumentVersion, setConsentDocumentVersion] = useState(study.settings.consentDocumentVersion);
  const [demographics, setDemographics] = useState(study.settings.demographics);
  const [consentAgreement, setConsentAgreement] = useState(study.settings.consentAgreement);
  const [neutralTitle, setNeutralTitle] = useState(study.settings.neutralTitle);
  const update = useMutation(
    trpc.studies.update.mutationOptions({
      onSuccess: () => queryClient.invalidateQueries({ queryKey: trpc.studies.get.queryKey({ studyId: study.id }) }),
    }),
  );
  if (!editable) {
    return (
      <Card className="p-6">
        <h2 className="font-semibold">About this study</h2>
        <p className="mt-2 whitespace-pre-wrap text-slate-700">{study.description || "No description."}</p>
      </Card>
    );
  }
  const submit = (e: FormEvent) => {
    e.preventDefault();
    update.mutate({
      studyId: study.id,
      title,
      description,
      status,
      settings: { requireConsent, blinding, consentDocumentVersion, consentAgreement, neutralTitle, demographics },
    });
  };
  return (
    <div className="space-y-6">
      <Card className="max-w-2xl p-6">
        <form onSubmit={submit} className="space-y-4">
          <Field label="Title" required error={fieldError(update.error, "title")}>
            {(p) => <Input {...p} value={title} onChange={(e) => setTitle(e.target.value)} />}
          </Field>
          <Field
            label="Name shown to participants"
            hint="On every participant page, and to wizards and observers blind to condition, in place of the title. Empty: the title."
            error={fieldError(update.error, "settings.neutralTitle")}
          >
            {(p) => <Input {...p} value={neutralTitle} onChange={(e) => setNeutralTitle(e.target.value)} />}
          </Field>
          <Field label="Description">
            {(p) => <Textarea {...p} value={description} onChange={(e) => setDescription(e.target.value)} />}
          </Field>
          <Field label="Status" hint={STUDY_STATUS_HINT}>
            {(p) => (
              <NativeSelect {...p} value={status} onChange={(e) => setStatus(e.target.value as StudyStatus)}>
                {STUDY_STATUSES.map((s) => (
                  <option key={s} value={s}>
                    {s}
                  </option>
                ))}
              </NativeSelect>
            )}
          </Field>
          <label className="flex items-center gap-2 text-sm">
            <input
              type="checkbox"
              className="h-4 w-4"
              checked={requireConsent}
              onChange={(e) => setRequireConsent(e.target.checked)}
            />
            Trials need a participant whose consent is recorded
          </label>
          <Field
            label="Consent document version"
            hint="Recorded with each consent, so you know which text a participant agreed to."
          >
            {(p) => (
              <Input
                {...p}
                value={consentDocumentVersion}
                onChange={(e) => setConsentDocumentVersion(e.target.value)}
              />
            )}
          </Field>
          <Field
            label="Words beside the consent checkbox"
            hint="What a participant ticks on a questionnaire's consent item."
            error={fieldError(update.error, "settings.consentAgreement")}
          >
            {(p) => <Input {...p} value={consentAgreement} onChange={(e) => setConsentAgreement(e.target.value)} />}
          </Field>
          <fieldset className="space-y-2 rounded-md border border-slate-200 p-3">
            <legend className="px-1 text-sm font-medium text-slate-700">Blinding</legend>
            {BLINDS.map(({ key, label, hint }) => (
              <label key={key} className="flex items-start gap-2 text-sm">
                <input
                  type="checkbox"
                  className="mt-0.5 h-4 w-4"
                  checked={blinding[key]}
                  onChange={(e) => setBlinding({ ...blinding, [key]: e.target.checked })}
                />
                <span>
                  {label}
                  <span className="block text-xs text-slate-500">{hint}</span>
                </span>
              </label>
            ))}
          </fieldset>
          <DemographicsEditor fields={demographics} onChange={setDemographics} />
          {update.error && !fieldError(update.error, "title") && <Problem error={update.error} />}
          <div className="flex items-center gap-3">
            <Button type="submit" disabled={update.isPending}>
              Save changes
            </Button>
            {update.isSuccess && <span className="text-sm text-emerald-700">Saved.</span>}
          </div>
        </form>
      </Card>
      {studyRoleMay(study.myRole, "study.delete") && <DeleteStudy study={study} />}
    </div>
  );
}
