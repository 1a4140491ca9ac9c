"use client";
// The properties of a "Play audio" action: which of the study's sounds, and
// who plays it on this robot. Choosing a file writes its id with its name and
// content hash, so the published version pins the very sound chosen.
import { useQuery, useQueryClient } from "@tanstack/react-query";
import { commands } from "@/core/designer/model";
import type { Command } from "@/core/designer/history";
import type { DesignAction } from "@/core/designer/types";
import { audioPlayerText, type AudioPlayer } from "@/core/plugins";
import { audioLength, audioUrl } from "@/lib/audio-upload";
import { useTRPC } from "@/lib/trpc";
import { Field, NativeSelect } from "@/ui/field";
import { AddSound } from "../studies/sounds-tab";

export function AudioChooser({
  studyId,
  action,
  player,
  robotName,
  run,
}: {
  studyId: string;
  action: DesignAction;
  player: AudioPlayer;
  robotName: string;
  run: (c: Command) => void;
}) {
  const trpc = useTRPC();
  const queryClient = useQueryClient();
  const files = useQuery(trpc.audio.list.queryOptions({ studyId }));
  const chosen = typeof action.parameters.fileId === "string" ? action.parameters.fileId : "";
  const file = files.data?.find((f) => f.id === chosen);
  type File = NonNullable<typeof files.data>[number];
  const use = (f: File | undefined) => {
    run(commands.setParameter(action.id, "fileId", f?.id));
    run(commands.setParameter(action.id, "name", f?.name));
    run(commands.setParameter(action.id, "sha256", f?.sha256));
    run(commands.setParameter(action.id, "durationMs", f?.durationMs ?? undefined));
  };
  const choose = (id: string) => use(files.data?.find((x) => x.id === id));
  // A file just uploaded here is the one meant: chosen at once.
  const added = async (id: string) => {
    await queryClient.invalidateQueries({ queryKey: trpc.audio.list.queryKey({ studyId }) });
    const list = await queryClient.fetchQuery(trpc.audio.list.queryOptions({ studyId }));
    use(list.find((x) => x.id === id));
  };
  const missing = chosen && files.data && !file;
  return (
    <div className="space-y-2">
      <Field
        label="Sound"
        required
        error={
          !chosen
            ? "Choose the sound to play."
            : missing
              ? `“${String(action.parameters.name ?? "")}” is no longer among the study's sounds: choose another.`
              : undefined
        }
      >
        {(p) => (
          <NativeSelect {...p} value={file ? chosen : ""} onChange={(e) => choose(e.target.value)}>
            <option value="">Choose a sound…</option>
            {files.data?.map((f) => (
              <option key={f.id} value={f.id}>
                {f.name} ({audioLength(f.durationMs)})
              </option>
            ))}
          </NativeSelect>
        )}
      </Field>
      {file && (
        // biome-ignore lint/a11y/useMediaCaption: the researcher's own sound file; there is no caption track to give
        <audio controls preload="none" src={audioUrl(file.id)} aria-label={`Listen to ${file.name}`} />
      )}
      <AddSound studyId={studyId} onAdded={(id) => void added(id)} />
      <p className="text-xs text-slate-600" data-testid="audio-player">
        On {robotName}: {audioPlayerText(player)}
        {player === "browser"
          ? " (its plugin has no way to play a file; keep the wizard's speakers near the participant)."
          : "."}
      </p>
    </div>
  );
}
