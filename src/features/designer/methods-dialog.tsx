"use client";
// The latest published version described for a paper's methods section:
// previewed here, copied as Markdown or plain text, or downloaded.
import { useQuery } from "@tanstack/react-query";
import { FileText } from "lucide-react";
import { useState } from "react";
import { useTRPC } from "@/lib/trpc";
import { Button } from "@/ui/button";
import { Dialog } from "@/ui/dialog";
import { MethodsText } from "@/ui/methods-text";
import { Problem } from "@/ui/problem";

export function MethodsDialog({ versionId, version }: { versionId: string; version: number }) {
  const trpc = useTRPC();
  const [open, setOpen] = useState(false);
  const methods = useQuery({ ...trpc.versions.methods.queryOptions({ versionId }), enabled: open });
  return (
    <Dialog
      title={`Methods text of version ${version}`}
      description="A description of this version for a paper's methods section, generated from what was published."
      size="wide"
      open={open}
      // Closed, the text and its "Copied" unmount: opened again, it starts afresh.
      onOpenChange={setOpen}
      trigger={
        <Button variant="secondary" size="sm">
          <FileText className="h-4 w-4" aria-hidden /> Methods text
        </Button>
      }
    >
      <Problem error={methods.error} />
      {methods.isPending && <p className="text-sm text-slate-500">Writing the description…</p>}
      {methods.data && <MethodsText methods={methods.data} />}
    </Dialog>
  );
}
