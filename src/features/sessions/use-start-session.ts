"use client";
// One click from a planned session to its live trial: the server makes the
// trial on the condition's published version (or reopens the one it made).
import { useMutation } from "@tanstack/react-query";
import { useRouter } from "next/navigation";
import { useTRPC } from "@/lib/trpc";

export function useStartSession() {
  const trpc = useTRPC();
  const router = useRouter();
  return useMutation(
    trpc.sessions.start.mutationOptions({ onSuccess: ({ trialId }) => router.push(`/trials/${trialId}`) }),
  );
}
