"use client";
// Deleting a study is for its owner alone and cannot be undone: every
// experiment, trial, recording and answer goes with it. The owner types the
// study's title to confirm, and the server checks that title again.
import { useMutation } from "@tanstack/react-query";
import { Trash2 } from "lucide-react";
import { useRouter } from "next/navigation";
import { useState } from "react";
import { useTRPC } from "@/lib/trpc";
import { Button } from "@/ui/button";
import { Dialog } from "@/ui/dialog";
import { Field, Input } from "@/ui/field";
import { Problem } from "@/ui/problem";

export function DeleteStudy({ study }: { study: { id: string; title: string } }) {
  const trpc = useTRPC();
  const router = useRouter();
  const [open, setOpen] = useState(false);
  const [typed, setTyped] = useState("");
  const remove = useMutation(trpc.studies.delete.mutationOptions({ onSuccess: () => router.push("/studies") }));
  return (
    <section aria-label="Delete the study" className="max-w-2xl rounded-lg border border-red-200 bg-white p-6">
      <h2 className="font-semibold text-red-800">Delete this study</h2>
      <p className="mt-1 text-sm text-slate-700">
        Its experiments, trials, recordings and answers are deleted with it, for good. Download the whole study from the
        Trials tab first if you may need them.
      </p>
      <Dialog
        title="Delete this study?"
        description="This cannot be undone."
        open={open}
        onOpenChange={(o) => {
          setOpen(o);
          setTyped("");
          remove.reset();
        }}
        trigger={
          <Button variant="secondary" className="mt-3 text-red-800">
            <Trash2 className="h-4 w-4" aria-hidden /> Delete study…
          </Button>
        }
      >
        <form
          className="space-y-3"
          onSubmit={(e) => {
            e.preventDefault();
            remove.mutate({ studyId: study.id, confirmTitle: typed });
          }}
        >
          <Field label={`Type the study's title, “${study.title}”, to confirm`}>
            {(p) => <Input {...p} value={typed} onChange={(e) => setTyped(e.target.value)} autoComplete="off" />}
          </Field>
          {remove.error && <Problem error={remove.error} />}
          <Button
            type="submit"
            disabled={typed !== study.title || remove.isPending}
            className="bg-red-700 hover:bg-red-800"
          >
            Delete the study and all its data
          </Button>
        </form>
      </Dialog>
    </section>
  );
}
