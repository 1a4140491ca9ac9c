"use client";
// Administrators add plugin repositories and sync them; what changed is shown
// in plain words, and every plugin document experiments can run is listed by
// its identity: source, version and a short hash, with which one an
// experiment that has not chosen runs when several sources offer a robot.
import { useMutation, useQuery, useQueryClient } from "@tanstack/react-query";
import { useState, type FormEvent } from "react";
import { shortHash } from "@/core/plugins";
import { useTRPC } from "@/lib/trpc";
import { Button } from "@/ui/button";
import { Field, Input } from "@/ui/field";
import { fieldError, Problem } from "@/ui/problem";
import { Select } from "@/ui/select";
import { Badge, Card, EmptyState, Spinner } from "@/ui/surface";
import { Table, Td, Th } from "@/ui/table";
import { clockDateTime } from "@/ui/clock-time";

const TRUST_TONE = { official: "green", verified: "blue", community: "amber" } as const;
type Trust = keyof typeof TRUST_TONE;

// What the administrator vouches for: no plugin of the repository is trusted more, whatever its files say.
const TRUST_CHOICES: Array<{ value: Trust; label: string; hint: string }> = [
  { value: "community", label: "Community", hint: "Anyone's plugins: check them before a study relies on them." },
  { value: "verified", label: "Verified", hint: "A source your lab has checked and relies on." },
  { value: "official", label: "Official", hint: "Maintained by the HRIStudio team or your own lab." },
];

export function PluginsPage() {
  const trpc = useTRPC();
  const queryClient = useQueryClient();
  const repositories = useQuery(trpc.plugins.repositories.list.queryOptions());
  const robots = useQuery(trpc.plugins.list.queryOptions());
  const [url, setUrl] = useState("");
  const [trust, setTrust] = useState<Trust>("community");
  const refresh = () =>
    Promise.all([
      queryClient.invalidateQueries({ queryKey: trpc.plugins.repositories.list.queryKey() }),
      queryClient.invalidateQueries({ queryKey: trpc.plugins.list.queryKey() }),
    ]);
  const add = useMutation(
    trpc.plugins.repositories.add.mutationOptions({ onSuccess: () => (setUrl(""), setTrust("community"), refresh()) }),
  );
  const sync = useMutation(trpc.plugins.repositories.sync.mutationOptions({ onSuccess: refresh }));
  const remove = useMutation(trpc.plugins.repositories.remove.mutationOptions({ onSuccess: refresh }));
  const submit = (e: FormEvent) => {
    e.preventDefault();
    add.mutate({ url, trust });
  };
  return (
    <div className="space-y-6">
      <h1 className="text-2xl font-semibold">Robot plugins</h1>
      <Card className="p-5">
        <h2 className="mb-3 font-semibold">Add a plugin repository</h2>
        <form onSubmit={submit} className="flex flex-wrap items-end gap-3">
          <div className="min-w-96 flex-1">
            <Field
              label="Repository address"
              required
              error={fieldError(add.error, "url")}
              hint="The folder that holds repository.json, e.g. https://repo.example.org/"
            >
              {(p) => <Input {...p} value={url} onChange={(e) => setUrl(e.target.value)} />}
            </Field>
          </div>
          <div className="w-56">
            <Field label="Trust" error={fieldError(add.error, "trust")} hint="The most its plugins are trusted.">
              {(p) => <Select {...p} value={trust} onValueChange={setTrust} options={TRUST_CHOICES} />}
            </Field>
          </div>
          <Button type="submit" className="mb-5" disabled={add.isPending}>
            Add repository
          </Button>
        </form>
        {add.error && !fieldError(add.error, "url") && <Problem error={add.error} />}
      </Card>

      <Problem error={repositories.error ?? sync.error ?? remove.error} />
      {sync.isPending && <Spinner label="Syncing: fetching and checking every plugin file…" />}
      {sync.data && (
        <Card role="region" className="p-5 text-sm" aria-label="What the last sync changed">
          <h2 className="mb-2 font-semibold">What the last sync changed</h2>
          <ul className="space-y-1">
            {sync.data.changes.map((c) => (
              <li key={c.robotId}>
                <strong>{c.robotId}</strong>: {c.change}
                {c.change === "updated" && ` from ${c.fromVersion} to ${c.toVersion}`}
                {c.change === "added" && ` (version ${c.toVersion})`}
                {c.actions.added.length > 0 && `; new actions: ${c.actions.added.join(", ")}`}
                {c.actions.removed.length > 0 && `; removed actions: ${c.actions.removed.join(", ")}`}
              </li>
            ))}
          </ul>
          {sync.data.notices.length > 0 && (
            <div className="mt-3">
              <p className="font-medium">Installed beside another source's plugin:</p>
              <ul className="list-disc pl-5">
                {sync.data.notices.map((n) => (
                  <li key={n}>{n}</li>
                ))}
              </ul>
            </div>
          )}
          {sync.data.errors.length > 0 && (
            <div className="mt-3">
              <p className="font-medium text-red-700">Not installed:</p>
              <ul className="list-disc pl-5 text-red-700">
                {sync.data.errors.map((e) => (
                  <li key={e}>{e}</li>
                ))}
              </ul>
            </div>
          )}
        </Card>
      )}
      {repositories.data?.length === 0 && (
        <EmptyState title="No repositories yet.">The first-party robots below are always available.</EmptyState>
      )}
      {!!repositories.data?.length && (
        <Table>
          <thead>
            <tr>
              <Th>Repository</Th>
              <Th>Trust</Th>
              <Th>Last synced</Th>
              <Th className="text-right">Actions</Th>
            </tr>
          </thead>
          <tbody>
            {repositories.data.map((r) => (
              <tr key={r.id}>
                <Td>
                  <div className="font-medium">{r.name}</div>
                  <div className="text-xs text-slate-500">{r.url}</div>
                </Td>
                <Td>
                  <Badge tone={TRUST_TONE[r.trust]}>{r.trust}</Badge>
                </Td>
                <Td>{r.lastSyncedAt ? clockDateTime(r.lastSyncedAt) : "never"}</Td>
                <Td className="text-right">
                  <Button
                    size="sm"
                    variant="secondary"
                    aria-label={`Sync now: ${r.name}`}
                    disabled={sync.isPending}
                    onClick={() => sync.mutate({ repositoryId: r.id })}
                  >
                    Sync now
                  </Button>
                  <Button
                    size="sm"
                    variant="ghost"
                    className="ml-2 text-red-800"
                    aria-label={`Remove: ${r.name}`}
                    disabled={remove.isPending}
                    onClick={() => {
                      if (
                        window.confirm(
                          `Remove ${r.name}? Its robots stay available to experiments already published with them.`,
                        )
                      )
                        remove.mutate({ repositoryId: r.id });
                    }}
                  >
                    Remove
                  </Button>
                </Td>
              </tr>
            ))}
          </tbody>
        </Table>
      )}

      <h2 className="pt-2 text-lg font-semibold">Robots available to experiments</h2>
      {robots.data?.problems.map((p) => (
        <Problem key={p} error={{ message: `A plugin file could not be loaded: ${p}` }} />
      ))}
      <Table>
        <thead>
          <tr>
            <Th>Robot</Th>
            <Th>Version</Th>
            <Th>Document</Th>
            <Th>Trust</Th>
            <Th>Connects by</Th>
            <Th>From</Th>
          </tr>
        </thead>
        <tbody>
          {robots.data?.robots.map((r, _, all) => (
            <tr key={`${r.sourceId} ${r.robotId}`}>
              <Td>
                <div className="font-medium">{r.name}</div>
                <code className="text-xs text-slate-500">{r.robotId}</code>
              </Td>
              <Td>{r.version}</Td>
              <Td>
                <code className="text-xs" title={r.hash}>
                  {shortHash(r.hash)}
                </code>
              </Td>
              <Td>
                <Badge tone={TRUST_TONE[r.trustLevel as keyof typeof TRUST_TONE] ?? "slate"}>{r.trustLevel}</Badge>
              </Td>
              <Td>{r.transport}</Td>
              <Td>
                {r.sourceName}
                {all.some((o) => o.robotId === r.robotId && o !== r) && (
                  <div className="text-xs text-slate-500">
                    {r.isDefault
                      ? "Run by experiments that have not chosen"
                      : "Run only by experiments that choose it in the designer"}
                  </div>
                )}
              </Td>
            </tr>
          ))}
        </tbody>
      </Table>
    </div>
  );
}
