"use client";
// The study's sounds: the files its "Play audio" actions play, added here or
// in the designer, each listened to before use. A file a published version
// plays cannot be deleted; the server names the version.
import { useMutation, useQuery, useQueryClient } from "@tanstack/react-query";
import { useState } from "react";
import { studyRoleMay, type StudyRole } from "@/core/access/policy";
import { audioLength, audioUrl, uploadAudio } from "@/lib/audio-upload";
import { useTRPC } from "@/lib/trpc";
import { Button } from "@/ui/button";
import { ListView } from "@/ui/list-view";
import { EmptyState } from "@/ui/surface";
import { Td, Th } from "@/ui/table";

export function SoundsTab({ studyId, role }: { studyId: string; role: StudyRole }) {
  const trpc = useTRPC();
  const queryClient = useQueryClient();
  const list = useQuery(trpc.audio.list.queryOptions({ studyId }));
  const refresh = () => queryClient.invalidateQueries({ queryKey: trpc.audio.list.queryKey({ studyId }) });
  const remove = useMutation(trpc.audio.remove.mutationOptions({ onSuccess: refresh }));
  const edit = studyRoleMay(role, "experiment.edit");
  // Only those who run trials may fetch a sound to hear it.
  const listen = studyRoleMay(role, "trial.run");
  return (
    <div className="space-y-4">
      <p className="text-sm text-slate-600">
        Sounds the robot (or, where it cannot, the wizard&apos;s browser) plays with a “Play audio” action. WAV, MP3 or
        Ogg, up to 20 MB.
      </p>
      {edit && <AddSound studyId={studyId} onAdded={refresh} />}
      <ListView
        query={list}
        label="Sounds"
        problem={remove.error}
        empty={<EmptyState title="No sounds yet.">Add a WAV, MP3 or Ogg file to play it in an experiment.</EmptyState>}
        columns={
          <>
            <Th>Sound</Th>
            <Th>Length</Th>
            {listen && <Th>Listen</Th>}
            {edit && <Th className="text-right">Actions</Th>}
          </>
        }
        row={(a) => (
          <tr key={a.id}>
            <Td>
              <div className="font-medium">{a.name}</div>
              <div className="font-mono text-xs text-slate-500" title="SHA-256 of the file">
                {a.sha256.slice(0, 12)}
              </div>
            </Td>
            <Td>{audioLength(a.durationMs)}</Td>
            {listen && (
              <Td>
                {/* biome-ignore lint/a11y/useMediaCaption: the researcher's own sound file; there is no caption track to give */}
                <audio controls preload="none" src={audioUrl(a.id)} aria-label={`Listen to ${a.name}`} />
              </Td>
            )}
            {edit && (
              <Td className="text-right">
                <Button
                  variant="ghost"
                  size="sm"
                  className="text-red-700"
                  aria-label={`Delete ${a.name}`}
                  onClick={() => remove.mutate({ audioFileId: a.id })}
                >
                  Delete
                </Button>
              </Td>
            )}
          </tr>
        )}
      />
    </div>
  );
}

/** A file picker that uploads what is picked; exported for the designer's Play audio chooser. */
export function AddSound({ studyId, onAdded }: { studyId: string; onAdded: (id: string) => void }) {
  const [state, setState] = useState<{ busy: boolean; error: string | null }>({ busy: false, error: null });
  return (
    <div className="space-y-1">
      <label className="inline-flex cursor-pointer items-center gap-2 text-sm font-medium text-slate-700">
        {state.busy ? "Uploading…" : "Add a sound file"}
        <input
          type="file"
          accept="audio/wav,audio/x-wav,audio/mpeg,audio/ogg,.wav,.mp3,.ogg,.oga,.opus"
          className="text-sm"
          disabled={state.busy}
          onChange={async (e) => {
            const file = e.target.files?.[0];
            e.target.value = "";
            if (!file) return;
            setState({ busy: true, error: null });
            try {
              onAdded((await uploadAudio(studyId, file)).id);
              setState({ busy: false, error: null });
            } catch (error) {
              setState({ busy: false, error: (error as Error).message });
            }
          }}
        />
      </label>
      {state.error && (
        <p role="alert" className="text-sm text-red-700">
          {state.error}
        </p>
      )}
    </div>
  );
}
