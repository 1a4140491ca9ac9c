"use client";
// Administrators read who changed what: accounts, studies, members, consent
// and plugins, newest first, one area at a time if they like.
import { keepPreviousData, useQuery } from "@tanstack/react-query";
import { useState } from "react";
import { actionWords, AUDIT_AREAS, detailLines, type AuditArea } from "@/core/access/audit";
import { useTRPC } from "@/lib/trpc";
import { Button } from "@/ui/button";
import { Field, NativeSelect } from "@/ui/field";
import { EmptyState } from "@/ui/surface";
import { ListView } from "@/ui/list-view";
import { Td, Th } from "@/ui/table";
import { clockDateTime } from "@/ui/clock-time";

const PAGE = 100;
const MOST = 500; // what admin.auditLog returns at most

export function AuditLogPage() {
  const trpc = useTRPC();
  const [area, setArea] = useState<AuditArea | "">("");
  const [limit, setLimit] = useState(PAGE);
  // The rows already shown stay while more (or another area) load.
  const entries = useQuery({
    ...trpc.admin.auditLog.queryOptions({ limit, area: area || undefined }),
    placeholderData: keepPreviousData,
  });
  const more = entries.data?.length === limit && limit < MOST;
  return (
    <div className="space-y-6">
      <h1 className="text-2xl font-semibold">Audit log</h1>
      <div className="flex flex-wrap items-end gap-3">
        <div className="w-64">
          <Field label="Show" hint="Newest first.">
            {(p) => (
              <NativeSelect
                {...p}
                value={area}
                onChange={(e) => {
                  setArea(e.target.value as AuditArea | "");
                  setLimit(PAGE);
                }}
              >
                <option value="">Everything</option>
                {AUDIT_AREAS.map((a) => (
                  <option key={a.value} value={a.value}>
                    {a.label}
                  </option>
                ))}
              </NativeSelect>
            )}
          </Field>
        </div>
      </div>
      <ListView
        query={entries}
        empty={
          <EmptyState title={area ? "Nothing recorded in this area yet." : "Nothing recorded yet."}>
            Changes to accounts, studies, members, consent and plugins appear here.
          </EmptyState>
        }
        label="Audit log"
        columns={
          <>
            <Th>Time</Th>
            <Th>Who</Th>
            <Th>Study</Th>
            <Th>What</Th>
            <Th>About</Th>
            <Th>Details</Th>
          </>
        }
        row={(e) => (
          <tr key={e.id} className="align-top">
            <Td className="whitespace-nowrap">{clockDateTime(e.at)}</Td>
            {/* No account: the participant's own consent form, or an account since deleted. */}
            <Td>{e.actor ?? <span className="text-slate-500">no account</span>}</Td>
            <Td>{e.studyTitle ?? "—"}</Td>
            <Td>
              <div>{actionWords(e.action)}</div>
              <div className="font-mono text-xs text-slate-500">{e.action}</div>
            </Td>
            <Td
              className={
                e.targetName || e.target === e.studyId ? undefined : "font-mono text-xs [overflow-wrap:anywhere]"
              }
            >
              {e.targetName ?? (e.target === e.studyId ? "the study" : e.target)}
            </Td>
            <Td className="max-w-sm">
              <Details details={e.details} />
            </Td>
          </tr>
        )}
      />
      {more && (
        <Button
          variant="secondary"
          disabled={entries.isFetching}
          onClick={() => setLimit(Math.min(limit + PAGE, MOST))}
        >
          {entries.isFetching ? "Loading…" : "Show older entries"}
        </Button>
      )}
    </div>
  );
}

function Details({ details }: { details: unknown }) {
  const lines = detailLines(details);
  if (lines.length === 0) return <span className="text-slate-500">—</span>;
  return (
    <dl className="grid grid-cols-[auto_1fr] gap-x-2 text-xs">
      {lines.map(([key, value], i) => (
        <div key={i} className="contents">
          <dt className="text-slate-500 [overflow-wrap:anywhere]">{key}</dt>
          <dd className="[overflow-wrap:anywhere]">{value}</dd>
        </div>
      ))}
    </dl>
  );
}
