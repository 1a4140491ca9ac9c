"use client";
// What the wizard's page, opened again, says of a recording the last page's
// closing cut off. A recording still open when the page opens is one whose
// page has just closed (or one recorded in another tab): it is asked about
// again until the server has finished it from its parts, or it goes on.
import { useQuery } from "@tanstack/react-query";
import { cutOffWords } from "@/core/media/recording-parts";
import { useTRPC } from "@/lib/trpc";
import { clockTime } from "@/ui/clock-time";

const OPEN_EVERY_MS = 5000;

export function useCutOff(trialId: string, enabled: boolean) {
  const trpc = useTRPC();
  const asked = useQuery({
    ...trpc.recordings.cutOff.queryOptions({ trialId }),
    enabled,
    refetchInterval: (query) => (query.state.data?.some((r) => r.status === "recording") ? OPEN_EVERY_MS : false),
  });
  const last = (asked.data ?? []).filter((r) => r.cutOff).at(-1);
  if (!last) return { words: null };
  const at = clockTime(last.stoppedAt);
  return { words: cutOffWords(at, last.status === "complete" ? (last.durationMs ?? 0) : null) };
}
