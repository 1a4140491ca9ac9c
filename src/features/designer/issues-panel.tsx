"use client";
// The validation panel: every problem in plain words, each a link to the
// block it is about. Errors stop publishing; warnings do not.
import { AlertCircle, AlertTriangle, CheckCircle2 } from "lucide-react";
import type { DesignIssue } from "@/core/designer/validate";
import type { DesignDraft } from "@/core/designer/types";
import { audioPlayerText, type AudioPlayer } from "@/core/plugins";
import type { Selection } from "./protocol-timeline";

export function IssuesPanel({
  draft,
  issues,
  robotName,
  audioPlayer,
  onSelect,
}: {
  draft: DesignDraft;
  issues: DesignIssue[];
  robotName: string;
  audioPlayer: AudioPlayer;
  onSelect: (s: Selection) => void;
}) {
  const errors = issues.filter((i) => i.severity === "error").length;
  const warnings = issues.length - errors;
  const actionCount = draft.steps.reduce((n, s) => n + s.actions.length, 0);
  const unsupported = issues.filter((i) => i.code === "unsupported_on_robot").length;
  const sounds = draft.steps.reduce((n, s) => n + s.actions.filter((a) => a.type === "play_audio").length, 0);
  return (
    <section aria-label="Checks" className="rounded-lg border border-slate-200 bg-white p-4 shadow-sm">
      <h2 className="mb-2 flex items-center gap-2 font-semibold">
        {errors ? (
          <AlertCircle className="h-4 w-4 text-red-600" aria-hidden />
        ) : (
          <CheckCircle2 className="h-4 w-4 text-emerald-600" aria-hidden />
        )}
        {errors ? `${errors} problem${errors > 1 ? "s" : ""} to fix before publishing` : "Ready to publish"}
        {warnings > 0 && (
          <span className="text-sm font-normal text-amber-800">
            · {warnings} warning{warnings > 1 ? "s" : ""}
          </span>
        )}
      </h2>
      <p className="mb-2 text-xs text-slate-500" data-testid="portability">
        {unsupported
          ? `${unsupported} of ${actionCount} actions cannot run on ${robotName}.`
          : `All ${actionCount} actions can run on ${robotName}.`}
        {sounds > 0 &&
          ` ${sounds === 1 ? "Its sound is" : `Its ${sounds} sounds are`} ${audioPlayerText(audioPlayer)}${audioPlayer === "browser" ? ` (${robotName} cannot play a file)` : ""}.`}
      </p>
      <ul className="max-h-64 space-y-1 overflow-y-auto text-sm">
        {issues.map((issue, n) => (
          <li key={n}>
            <button
              type="button"
              className="flex w-full items-start gap-1.5 rounded px-1 py-0.5 text-left hover:bg-slate-100"
              onClick={() =>
                onSelect(
                  issue.actionId
                    ? { kind: "action", id: issue.actionId }
                    : issue.stepId
                      ? { kind: "step", id: issue.stepId }
                      : null,
                )
              }
            >
              {issue.severity === "error" ? (
                <AlertCircle className="mt-0.5 h-4 w-4 shrink-0 text-red-600" aria-label="Error" />
              ) : (
                <AlertTriangle className="mt-0.5 h-4 w-4 shrink-0 text-amber-600" aria-label="Warning" />
              )}
              <span>
                {where(draft, issue)}
                {issue.message}
              </span>
            </button>
          </li>
        ))}
      </ul>
    </section>
  );
}

function where(draft: DesignDraft, issue: DesignIssue) {
  const index = draft.steps.findIndex((s) => s.id === issue.stepId);
  return index >= 0 ? <span className="font-medium">Step {index + 1}: </span> : null;
}
