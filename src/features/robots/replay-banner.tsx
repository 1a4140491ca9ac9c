"use client";
// Says on the robot page that what the simulated robot does now is a replay,
// of which trial, and how far it has got. The simulator names the trial by id
// only; its name comes from the server, which gives it to members of its study.
import { useQuery } from "@tanstack/react-query";
import Link from "next/link";
import type { ReplayAnnouncement } from "@/core/robots/robot-state";
import { useTRPC } from "@/lib/trpc";
import { seconds } from "@/ui/format";

export function ReplayBanner({ replay }: { replay: ReplayAnnouncement }) {
  const trpc = useTRPC();
  const trial = useQuery({ ...trpc.trials.get.queryOptions({ trialId: replay.trialId }), retry: false });
  const name = trial.data
    ? `${trial.data.experimentName} · ${trial.data.participantCode ?? "no participant"}`
    : trial.isError
      ? "a trial of a study you are not in"
      : "a trial";
  return (
    <div
      role="status"
      aria-label="Replay"
      className="rounded-md border border-violet-300 bg-violet-50 px-4 py-3 text-sm"
    >
      {replay.playing ? (
        <>
          <strong>Replay, not live:</strong> the robot is repeating the commands of{" "}
          {trial.data ? (
            <Link className="font-medium text-brand-600 hover:underline" href={`/trials/${replay.trialId}/analysis`}>
              {name}
            </Link>
          ) : (
            name
          )}{" "}
          at ×{replay.speed}, at {seconds(replay.positionMs)} of the trial ({replay.sent} of {replay.total} commands
          sent).
        </>
      ) : (
        <>The replay of {name} has ended.</>
      )}
    </div>
  );
}
