"use client";
// A methods text shown for reading, with buttons to copy it as Markdown or
// plain text and a link to download it: the designer's per-version text and
// the study's Methods tab show it the same way.
import { Download } from "lucide-react";
import { Button } from "./button";
import { Problem } from "./problem";
import { useCopy } from "./use-copy";

export function MethodsText({ methods }: { methods: { markdown: string; text: string; filename: string } }) {
  const { copied, copyError, copy } = useCopy();
  return (
    <div className="space-y-3">
      <Problem error={copyError} />
      <section
        aria-label="Methods text"
        // biome-ignore lint/a11y/noNoninteractiveTabindex: a scrollable region must take focus so the keyboard can scroll it (WCAG 2.1.1, axe's scrollable-region-focusable)
        tabIndex={0}
        className="max-h-[60vh] overflow-y-auto rounded border border-slate-200 bg-slate-50 p-3 focus:outline-none focus-visible:ring-2 focus-visible:ring-brand-600"
      >
        <pre className="whitespace-pre-wrap font-sans text-sm text-slate-800">{methods.text}</pre>
      </section>
      <div className="flex flex-wrap items-center gap-2">
        <Button size="sm" onClick={() => void copy("Markdown", methods.markdown)}>
          Copy Markdown
        </Button>
        <Button variant="secondary" size="sm" onClick={() => void copy("plain text", methods.text)}>
          Copy as plain text
        </Button>
        <a
          href={`data:text/markdown;charset=utf-8,${encodeURIComponent(methods.markdown)}`}
          download={methods.filename}
          className="inline-flex items-center gap-1.5 text-sm font-medium text-brand-600 hover:underline"
        >
          <Download className="h-4 w-4" aria-hidden /> Download {methods.filename}
        </a>
        {copied && (
          <span role="status" className="text-sm text-emerald-800">
            Copied as {copied}.
          </span>
        )}
      </div>
    </div>
  );
}
