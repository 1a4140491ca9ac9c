"use client";
// A download that shows its progress: large exports (a whole study) take a
// while, and a link that seems to do nothing gets clicked again. A file of
// known length shows its share received; the study's zip, streamed as it is
// made (its length unknown until its end), says how many trials it holds and
// shows how many of them have arrived.
import { Download } from "lucide-react";
import { useState } from "react";
import { isTrialRecord, zipEntryCounter } from "@/core/analysis/zip-progress";
import { Problem } from "./problem";

type Progress = { received: number; total: number | null; trials: { done: number; of: number } | null };

const megabytes = (bytes: number) => `${(bytes / 1_000_000).toFixed(1)} MB`;

export function DownloadLink({ href, children }: { href: string; children: React.ReactNode }) {
  const [progress, setProgress] = useState<Progress | null>(null);
  const [problem, setProblem] = useState<string | null>(null);
  const start = async () => {
    setProblem(null);
    setProgress({ received: 0, total: null, trials: null });
    let response: Response;
    try {
      response = await fetch(href);
    } catch {
      setProgress(null);
      return setProblem(
        "The download could not start: the server did not answer. Check your connection and try again.",
      );
    }
    try {
      if (!response.ok || !response.body) throw new Error(await response.text());
      const total = Number(response.headers.get("content-length") ?? 0) || null;
      const trials = response.headers.get("x-export-trials");
      const count = trials === null ? null : zipEntryCounter(isTrialRecord);
      const reader = response.body.getReader();
      const parts: Uint8Array<ArrayBuffer>[] = [];
      let received = 0;
      for (;;) {
        let read: Awaited<ReturnType<typeof reader.read>>;
        try {
          read = await reader.read();
        } catch {
          throw new Error(
            "it stopped before its end (the server could not finish the file). Try again; if it happens again, tell your administrator, whose server log says why.",
          );
        }
        if (read.done) break;
        parts.push(read.value);
        received += read.value.length;
        const done = count?.(read.value);
        setProgress({ received, total, trials: count ? { done: done!, of: Number(trials) } : null });
      }
      const name = /filename="([^"]+)"/.exec(response.headers.get("content-disposition") ?? "")?.[1] ?? "download";
      const url = URL.createObjectURL(
        new Blob(parts, { type: response.headers.get("content-type") ?? "application/octet-stream" }),
      );
      Object.assign(document.createElement("a"), { href: url, download: name }).click();
      URL.revokeObjectURL(url);
    } catch (error) {
      setProblem(`The download failed: ${(error as Error).message}`);
    } finally {
      setProgress(null);
    }
  };
  return (
    <div className="space-y-1">
      <button
        type="button"
        onClick={() => void start()}
        disabled={progress !== null}
        className="inline-flex items-center gap-1.5 text-sm font-medium text-brand-600 hover:underline disabled:text-slate-500"
      >
        <Download className="h-4 w-4" aria-hidden />
        {children}
      </button>
      {progress !== null && <DownloadProgress progress={progress} />}
      {problem && <Problem error={{ message: problem }} />}
    </div>
  );
}

function DownloadProgress({ progress: { received, total, trials } }: { progress: Progress }) {
  const share = trials ? (trials.of ? trials.done / trials.of : 1) : total ? received / total : null;
  const label = trials
    ? `${trials.done} of ${trials.of} trials · ${megabytes(received)}`
    : total
      ? `${megabytes(received)} of ${megabytes(total)}`
      : received
        ? megabytes(received)
        : "preparing…";
  return (
    <div role="status" className="flex items-center gap-2 text-xs text-slate-500">
      {/* Without a share known yet the bar is indeterminate: it moves without claiming how far. */}
      <progress
        aria-label="Download progress"
        className="h-2 w-48"
        max={1}
        {...(share === null ? {} : { value: Math.min(1, share) })}
      />
      <span>{label}</span>
    </div>
  );
}
