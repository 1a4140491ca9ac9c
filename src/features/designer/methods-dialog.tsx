"use client";
// The latest published version described for a paper's methods section:
// previewed here, copied as Markdown or plain text, or downloaded.
import { useQuery } from "@tanstack/react-query";
import { Download, FileText } from "lucide-react";
import { useState } from "react";
import { useTRPC } from "@/lib/trpc";
import { Button } from "@/ui/button";
import { Dialog } from "@/ui/dialog";
import { Problem } from "@/ui/problem";

export function MethodsDialog({ versionId, version }: { versionId: string; version: number }) {
  const trpc = useTRPC();
  const [open, setOpen] = useState(false);
  const [copied, setCopied] = useState<string | null>(null);
  const [copyError, setCopyError] = useState<unknown>(null);
  const methods = useQuery({ ...trpc.versions.methods.queryOptions({ versionId }), enabled: open });
  const copy = async (what: string, text: string) => {
    setCopyError(null);
    try {
      await navigator.clipboard.writeText(text);
      setCopied(what);
    } catch {
      setCopyError({ message: "The browser did not allow copying: select the text and copy it by hand." });
    }
  };
  return (
    <Dialog
      title={`Methods text of version ${version}`}
      description="A description of this version for a paper's methods section, generated from what was published."
      size="wide"
      open={open}
      onOpenChange={(next) => {
        setOpen(next);
        setCopied(null);
      }}
      trigger={
        <Button variant="secondary" size="sm">
          <FileText className="h-4 w-4" aria-hidden /> Methods text
        </Button>
      }
    >
      <Problem error={methods.error ?? copyError} />
      {methods.isPending && <p className="text-sm text-slate-500">Writing the description…</p>}
      {methods.data && (
        <div className="space-y-3">
          <section
            aria-label="Methods text"
            // biome-ignore lint/a11y/noNoninteractiveTabindex: a scrollable region must take focus so the keyboard can scroll it (WCAG 2.1.1, axe's scrollable-region-focusable)
            tabIndex={0}
            className="max-h-[60vh] overflow-y-auto rounded border border-slate-200 bg-slate-50 p-3 focus:outline-none focus-visible:ring-2 focus-visible:ring-brand-600"
          >
            <pre className="whitespace-pre-wrap font-sans text-sm text-slate-800">{methods.data.text}</pre>
          </section>
          <div className="flex flex-wrap items-center gap-2">
            <Button size="sm" onClick={() => void copy("Markdown", methods.data.markdown)}>
              Copy Markdown
            </Button>
            <Button variant="secondary" size="sm" onClick={() => void copy("plain text", methods.data.text)}>
              Copy as plain text
            </Button>
            <a
              href={`data:text/markdown;charset=utf-8,${encodeURIComponent(methods.data.markdown)}`}
              download={methods.data.filename}
              className="inline-flex items-center gap-1.5 text-sm font-medium text-brand-600 hover:underline"
            >
              <Download className="h-4 w-4" aria-hidden /> Download {methods.data.filename}
            </a>
            {copied && (
              <span role="status" className="text-sm text-emerald-800">
                Copied as {copied}.
              </span>
            )}
          </div>
        </div>
      )}
    </Dialog>
  );
}
