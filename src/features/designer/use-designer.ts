"use client";
// The designer's state: the headless model's history, the draft's autosave,
// and what happens when someone else saved first (the researcher is told,
// and chooses; nothing is overwritten silently).
import { useMutation, useQuery } from "@tanstack/react-query";
import { useCallback, useEffect, useRef, useState } from "react";
import { execute, redo, startHistory, undo, type Command, type History } from "@/core/designer/history";
import { draftFrom } from "@/core/designer/draft";
import { describeSaveIssues, type FieldIssue } from "@/core/designer/save-problems";
import type { DesignDraft } from "@/core/designer/types";
import { newId } from "@/lib/new-id";
import { useTRPC } from "@/lib/trpc";
import { messageOf } from "@/ui/problem";

export type SaveState =
  | { kind: "saved" }
  | { kind: "saving" }
  | { kind: "unsaved" }
  | { kind: "conflict" }
  | { kind: "failed"; message: string };

const AUTOSAVE_DELAY_MS = 700;

export function useDesigner(experimentId: string) {
  const trpc = useTRPC();
  const loaded = useQuery(
    trpc.experiments.get.queryOptions({ experimentId }, { refetchOnWindowFocus: false, staleTime: Infinity }),
  );
  const [history, setHistory] = useState<History | null>(null);
  const [save, setSave] = useState<SaveState>({ kind: "saved" });
  const [notice, setNotice] = useState<string | null>(null);
  const current = useRef<History | null>(null);
  const revision = useRef(0);
  const savedDraft = useRef<DesignDraft | null>(null);
  const inFlight = useRef(false);

  const reset = useCallback((design: DesignDraft & { draftRevision: number }) => {
    const h = startHistory(draftFrom(design));
    current.current = h;
    savedDraft.current = h.present;
    revision.current = design.draftRevision;
    setHistory(h);
    setSave({ kind: "saved" });
  }, []);

  useEffect(() => {
    if (loaded.data && !current.current) reset(loaded.data);
  }, [loaded.data, reset]);

  const saveDesign = useMutation(trpc.experiments.saveDesign.mutationOptions());

  const flush = useCallback(async () => {
    const h = current.current;
    if (!h || inFlight.current || h.present === savedDraft.current) return;
    inFlight.current = true;
    setSave({ kind: "saving" });
    const draft = h.present;
    try {
      const result = await saveDesign.mutateAsync({
        experimentId,
        baseRevision: revision.current,
        details: { name: draft.name, description: draft.description, robotId: draft.robotId },
        steps: draft.steps.map((s) => ({ ...s, actions: s.actions.map((a) => ({ ...a })) })),
      });
      revision.current = result.draftRevision;
      savedDraft.current = draft;
      setSave(current.current?.present === draft ? { kind: "saved" } : { kind: "unsaved" });
    } catch (error) {
      const data = (error as { data?: { code?: string; issues?: FieldIssue[] | null } }).data;
      // A refused field is named by its step and action, never by the input's path.
      const message = data?.issues?.length ? describeSaveIssues(draft, data.issues) : messageOf(error);
      setSave(data?.code === "CONFLICT" ? { kind: "conflict" } : { kind: "failed", message });
    } finally {
      inFlight.current = false;
    }
  }, [experimentId, saveDesign]);

  // Autosave a moment after the last edit; a save in flight is followed by another if needed.
  useEffect(() => {
    if (!history || save.kind === "conflict" || save.kind === "saving") return;
    if (history.present === savedDraft.current) {
      if (save.kind === "unsaved") setSave({ kind: "saved" });
      return;
    }
    const timer = setTimeout(() => void flush(), AUTOSAVE_DELAY_MS);
    return () => clearTimeout(timer);
  }, [history, save.kind, flush]);

  const apply = useCallback((next: History) => {
    current.current = next;
    setHistory(next);
    setNotice(null);
    setSave((s) => (s.kind === "conflict" || s.kind === "saving" ? s : { kind: "unsaved" }));
  }, []);

  const run = useCallback(
    (command: Command) => {
      if (!current.current) return;
      try {
        apply(execute(current.current, command, newId));
      } catch (error) {
        setNotice((error as Error).message);
      }
    },
    [apply],
  );

  /** After a conflict: take what the other person saved, dropping these edits. */
  const loadTheirs = useCallback(async () => {
    const fresh = await loaded.refetch();
    if (fresh.data) reset(fresh.data);
  }, [loaded, reset]);

  /** After a conflict: save these edits over theirs, knowingly. */
  const keepMine = useCallback(async () => {
    const fresh = await loaded.refetch();
    if (!fresh.data) return;
    revision.current = fresh.data.draftRevision;
    savedDraft.current = null;
    setSave({ kind: "unsaved" });
    await flush();
  }, [loaded, flush]);

  return {
    loaded,
    history,
    draft: history?.present ?? null,
    run,
    undo: () => current.current && apply(undo(current.current)),
    redo: () => current.current && apply(redo(current.current)),
    save,
    saveNow: flush,
    notice,
    setNotice,
    loadTheirs,
    keepMine,
  };
}
