"use client";
// Which plugin document the experiment runs: its source, version and a short
// hash. When several sources offer the robot (a repository's copy of a
// first-party robot, say), the designer chooses one; the next published
// version pins exactly that document.
import { useMutation, useQueryClient } from "@tanstack/react-query";
import { chooseDocument, shortHash } from "@/core/plugins";
import { useTRPC } from "@/lib/trpc";
import { NativeSelect } from "@/ui/field";
import { Problem } from "@/ui/problem";

export interface PluginDocument {
  robotId: string;
  sourceId: string;
  sourceName: string;
  version: string;
  hash: string;
}

/** The documents of `robotId`, the default first, and the one an experiment with `chosenSource` runs. */
export function documentsOf<T extends PluginDocument>(documents: T[], robotId: string, chosenSource: string | null) {
  const offered = documents.filter((d) => d.robotId === robotId).map((d) => ({ ...d, source: d.sourceId }));
  return { offered, used: chooseDocument(offered, robotId, chosenSource) };
}

/** "the first-party plugins · 3.0.0 · 1a2b3c4d5e6f" */
const label = (d: PluginDocument) => `${d.sourceName} · ${d.version} · ${shortHash(d.hash)}`;

export function PluginChoice({
  experimentId,
  robotId,
  chosenSource,
  documents,
  canChoose,
}: {
  experimentId: string;
  robotId: string;
  /** The source the experiment recorded, or null for the default. */
  chosenSource: string | null;
  /** Every source's current document of every robot, the default of each robot first. */
  documents: PluginDocument[];
  /** False while editing is not allowed or the robot change is not saved yet. */
  canChoose: boolean;
}) {
  const trpc = useTRPC();
  const queryClient = useQueryClient();
  const choose = useMutation(
    trpc.experiments.choosePlugin.mutationOptions({
      onSuccess: () => queryClient.invalidateQueries({ queryKey: trpc.experiments.get.queryKey({ experimentId }) }),
    }),
  );
  const { offered, used } = documentsOf(documents, robotId, chosenSource);
  if (!offered.length)
    return (
      <span role="status" className="text-sm text-red-700">
        No plugin document of {robotId} is installed.
      </span>
    );
  if (offered.length === 1 && used)
    return (
      <span className="text-sm text-slate-600" title={`Plugin document ${used.hash}`}>
        Plugin: {label(used)}
      </span>
    );
  return (
    // biome-ignore lint/a11y/noLabelWithoutControl: the select inside is the control (a custom component the rule cannot see through)
    <label className="flex items-center gap-2 text-sm text-slate-600">
      Plugin
      <NativeSelect
        aria-label="Plugin document"
        title={`Which document of ${robotId} this experiment runs; its next published version pins it`}
        className="h-9 w-auto py-0"
        value={used?.sourceId ?? ""}
        disabled={!canChoose || choose.isPending}
        onChange={(e) => choose.mutate({ experimentId, source: e.target.value })}
      >
        {/* The source chosen stopped offering the robot (its repository removed): never another's in its place. */}
        {!used && (
          <option value="" disabled>
            No longer installed from the source chosen: choose one
          </option>
        )}
        {offered.map((d) => (
          <option key={d.sourceId} value={d.sourceId}>
            {label(d)}
          </option>
        ))}
      </NativeSelect>
      {choose.error && <Problem error={choose.error} />}
    </label>
  );
}
