"use client";
// Coding a finished trial afterwards, from the trial's page: its recording and
// my own tier. Nothing here is results, so an observer blind to condition
// codes here without the blind being lifted (the analysis page stays closed).
import { useState } from "react";
import { RecordingPlayer, useTrialRecording } from "../analysis/recording-player";
import { CodeTiers } from "./code-tiers";

export function CodeAfterwards({ trialId }: { trialId: string }) {
  const recording = useTrialRecording(trialId, true);
  const [playheadMs, setPlayheadMs] = useState<number | null>(null);
  return (
    <section aria-label="Code this trial afterwards" className="space-y-3">
      <RecordingPlayer recording={recording} gaps={[]} onTime={setPlayheadMs} />
      <CodeTiers trialId={trialId} playheadMs={playheadMs} mineOnly />
    </section>
  );
}
