"use client";
// Publishing and the published versions: trials run only a published version,
// so a version is frozen, numbered and hashed, and two can be compared.
import { useMutation, useQuery, useQueryClient } from "@tanstack/react-query";
import { Download, Upload } from "lucide-react";
import { useState } from "react";
import { unchangedSince, type PublishedVersion } from "@/core/designer/published";
import type { DesignDraft } from "@/core/designer/types";
import { useTRPC, useTRPCClient } from "@/lib/trpc";
import { Button } from "@/ui/button";
import { NativeSelect } from "@/ui/field";
import { Problem } from "@/ui/problem";
import { Badge } from "@/ui/surface";
import { MethodsDialog } from "./methods-dialog";
import { clockDateTime } from "@/ui/clock-time";

export function VersionsPanel({
  experimentId,
  draft,
  canPublish,
  blocked: problems,
  beforePublish,
  pluginHash,
}: {
  experimentId: string;
  draft: DesignDraft;
  /** The plugin document the draft runs now; undefined while not known. */
  pluginHash: string | undefined;
  canPublish: boolean;
  blocked: string | null;
  beforePublish: () => Promise<void>;
}) {
  const trpc = useTRPC();
  const client = useTRPCClient();
  const queryClient = useQueryClient();
  const versions = useQuery(trpc.versions.list.queryOptions({ experimentId }));
  const publish = useMutation(
    trpc.versions.publish.mutationOptions({
      onSuccess: () => queryClient.invalidateQueries({ queryKey: trpc.versions.list.queryKey({ experimentId }) }),
    }),
  );
  const [exportError, setExportError] = useState<unknown>(null);
  const download = async () => {
    setExportError(null);
    try {
      await beforePublish();
      const file = await client.experiments.exportFile.query({ experimentId });
      const url = URL.createObjectURL(new Blob([file.text], { type: "application/json" }));
      const link = Object.assign(document.createElement("a"), { href: url, download: file.fileName });
      link.click();
      URL.revokeObjectURL(url);
    } catch (error) {
      setExportError(error);
    }
  };
  const list = versions.data ?? [];
  // The newest version's content, to tell whether publishing would only copy it.
  const latest = useQuery({
    ...trpc.versions.get.queryOptions({ versionId: list[0]?.id ?? "" }),
    enabled: Boolean(list[0]),
  });
  const unchanged = latest.data && list[0] ? unchangedSince(draft, latest.data as PublishedVersion, pluginHash) : null;
  const blocked =
    problems ?? (unchanged === null ? null : `Published as version ${unchanged}; change the draft to publish again.`);
  return (
    <section aria-label="Versions" className="space-y-3 rounded-lg border border-slate-200 bg-white p-4 shadow-sm">
      <div className="flex flex-wrap items-center gap-2">
        <h2 className="mr-auto font-semibold">Versions</h2>
        {list[0] && <MethodsDialog versionId={list[0].id} version={list[0].version} />}
        <Button variant="secondary" size="sm" onClick={download}>
          <Download className="h-4 w-4" aria-hidden /> Export file
        </Button>
        {canPublish && (
          <Button
            size="sm"
            disabled={Boolean(blocked) || publish.isPending}
            title={blocked ?? "Freeze this draft as a new version that trials can run"}
            onClick={async () => {
              await beforePublish();
              publish.mutate({ experimentId });
            }}
          >
            <Upload className="h-4 w-4" aria-hidden /> {publish.isPending ? "Publishing…" : "Publish"}
          </Button>
        )}
      </div>
      {blocked && canPublish && <p className="text-xs text-slate-500">{blocked}</p>}
      <Problem error={publish.error ?? exportError} />
      {publish.data && (
        <p role="status" className="text-sm text-emerald-800">
          Published version {publish.data.version} (fingerprint {publish.data.hash.slice(0, 12)}).
        </p>
      )}
      {list.length === 0 ? (
        <p className="text-sm text-slate-500">Not published yet: trials can only rehearse the draft.</p>
      ) : (
        <ul className="space-y-1 text-sm">
          {list.map((v) => (
            <li key={v.id} className="flex items-center gap-2">
              <Badge tone="green">version {v.version}</Badge>
              <span className="text-slate-600">
                {clockDateTime(v.publishedAt)} · {v.publishedBy ?? "someone"}
              </span>
              <code className="ml-auto text-xs text-slate-500" title={v.hash}>
                {v.hash.slice(0, 8)}
              </code>
            </li>
          ))}
        </ul>
      )}
      {list.length >= 2 && <VersionDiff experimentId={experimentId} versions={list.map((v) => v.version)} />}
    </section>
  );
}

function VersionDiff({ experimentId, versions }: { experimentId: string; versions: number[] }) {
  const trpc = useTRPC();
  const [from, setFrom] = useState(versions[1]!);
  const [to, setTo] = useState(versions[0]!);
  const diff = useQuery(trpc.versions.diff.queryOptions({ experimentId, from, to }));
  const pick = (value: number, set: (n: number) => void, label: string) => (
    <NativeSelect
      aria-label={label}
      className="h-8 w-auto py-0"
      value={value}
      onChange={(e) => set(Number(e.target.value))}
    >
      {versions.map((v) => (
        <option key={v} value={v}>
          version {v}
        </option>
      ))}
    </NativeSelect>
  );
  return (
    <div className="space-y-2 border-t border-slate-100 pt-3">
      <div className="flex items-center gap-2 text-sm">
        Compare {pick(from, setFrom, "Compare from version")} with {pick(to, setTo, "Compare with version")}
      </div>
      <Problem error={diff.error} />
      {diff.data && (
        <ul aria-label="Changes between versions" className="space-y-0.5 text-sm">
          {diff.data.length === 0 && <li className="text-slate-500">No differences.</li>}
          {diff.data.map((line, i) => (
            <li
              key={i}
              className={
                line.kind === "added" ? "text-emerald-800" : line.kind === "removed" ? "text-red-800" : "text-slate-700"
              }
            >
              {line.kind === "added" ? "+ " : line.kind === "removed" ? "− " : "• "}
              {line.text}
            </li>
          ))}
        </ul>
      )}
    </div>
  );
}
