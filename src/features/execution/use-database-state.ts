"use client";
// The database as the web app finds it, asked every few seconds while the
// wizard's page is open: the session lookup behind the smallest question is
// the web app's first question to the database, answered 503 within seconds
// when the database does not answer (src/server/context.ts).
import { useQuery } from "@tanstack/react-query";
import type { DatabaseState } from "@/core/trial/connections";
import { useTRPC } from "@/lib/trpc";

const EVERY_MS = 5000;

export function useDatabaseState(): DatabaseState {
  const trpc = useTRPC();
  const probe = useQuery({
    ...trpc.account.me.queryOptions(),
    refetchInterval: EVERY_MS,
    refetchIntervalInBackground: true,
    staleTime: 0,
    retry: false,
  });
  if (probe.error) return probe.error.data?.httpStatus === 503 ? "unavailable" : "checking";
  return probe.isSuccess ? "connected" : "checking";
}
