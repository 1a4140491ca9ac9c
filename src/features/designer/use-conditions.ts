"use client";
// The names of the study's conditions that run this experiment: the
// conditions an action or a step may vary for (variants are kept by condition name).
import { useQuery } from "@tanstack/react-query";
import { useMemo } from "react";
import { useTRPC } from "@/lib/trpc";

const NONE: string[] = [];

export function useConditionNames(studyId: string | undefined, experimentId: string): string[] {
  const trpc = useTRPC();
  const listed = useQuery({
    ...trpc.conditions.list.queryOptions({ studyId: studyId ?? "" }),
    enabled: Boolean(studyId),
  });
  return useMemo(
    () => listed.data?.filter((c) => c.experimentId === experimentId).map((c) => c.name) ?? NONE,
    [listed.data, experimentId],
  );
}
