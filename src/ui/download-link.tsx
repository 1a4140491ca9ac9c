"use client";
// A download that shows its progress: large exports (a whole study) take a
// while, and a link that seems to do nothing gets clicked again.
import { Download } from "lucide-react";
import { useState } from "react";
import { Problem } from "./problem";

export function DownloadLink({ href, children }: { href: string; children: React.ReactNode }) {
  const [progress, setProgress] = useState<number | null>(null);
  const [problem, setProblem] = useState<string | null>(null);
  const start = async () => {
    setProblem(null);
    setProgress(0);
    try {
      const response = await fetch(href);
      if (!response.ok || !response.body) throw new Error(await response.text());
      const total = Number(response.headers.get("content-length") ?? 0);
      const reader = response.body.getReader();
      const parts: Uint8Array<ArrayBuffer>[] = [];
      let received = 0;
      for (;;) {
        const { done, value } = await reader.read();
        if (done) break;
        parts.push(value);
        received += value.length;
        setProgress(total ? received / total : null);
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
        {progress !== null && (
          <span role="status" className="ml-2 text-xs text-slate-500">
            {progress ? `${Math.round(progress * 100)} %` : "preparing…"}
          </span>
        )}
      </button>
      {problem && <Problem error={{ message: problem }} />}
    </div>
  );
}
