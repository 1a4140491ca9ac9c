"use client";
// Personal access tokens for the analysis API: make one for chosen studies,
// copy its secret (shown this once), see where each is used, revoke it.
import { useMutation, useQuery, useQueryClient } from "@tanstack/react-query";
import Link from "next/link";
import { useTRPC } from "@/lib/trpc";
import { Button } from "@/ui/button";
import { ListView } from "@/ui/list-view";
import { Badge } from "@/ui/surface";
import { Td, Th } from "@/ui/table";
import { NewToken } from "./new-token";
import { clockDateTime } from "@/ui/clock-time";

const STATE_TONE = { active: "green", expired: "slate", revoked: "red" } as const;

const when = (at: Date | string | null) => (at ? clockDateTime(at) : "never");

export function AccessTokensPage() {
  const trpc = useTRPC();
  const queryClient = useQueryClient();
  const tokens = useQuery(trpc.tokens.list.queryOptions());
  const refresh = () => queryClient.invalidateQueries({ queryKey: trpc.tokens.list.queryKey() });
  const revoke = useMutation(trpc.tokens.revoke.mutationOptions({ onSuccess: refresh }));
  return (
    <div className="space-y-6">
      <div>
        <h1 className="text-2xl font-semibold">Access tokens</h1>
        <p className="mt-1 max-w-3xl text-sm text-slate-600">
          A token lets a script in R or Python read the data of the studies you choose, through the analysis API
          (documented in <code>docs/analysis-api.md</code>; its description is at{" "}
          <Link className="text-brand-700 underline" href="/api/v1/openapi.json">
            /api/v1/openapi.json
          </Link>
          ). It can only read, never change anything, and it never reaches more than you can: if you leave a study, the
          token stops working for it.
        </p>
      </div>
      <NewToken onCreated={refresh} />
      <ListView
        query={tokens}
        problem={revoke.error}
        label="Your access tokens"
        empty={<p className="text-sm text-slate-600">You have no access tokens yet.</p>}
        columns={
          <>
            <Th>Name</Th>
            <Th>Studies</Th>
            <Th>Created</Th>
            <Th>Expires</Th>
            <Th>Last used</Th>
            <Th>State</Th>
            <Th className="text-right">Actions</Th>
          </>
        }
        row={(t) => (
          <tr key={t.id}>
            <Td className="font-medium">{t.name}</Td>
            <Td>{t.studies.map((s) => s.title).join(", ") || "none left"}</Td>
            <Td className="whitespace-nowrap">{when(t.createdAt)}</Td>
            <Td className="whitespace-nowrap">{when(t.expiresAt)}</Td>
            <Td className="whitespace-nowrap">{when(t.lastUsedAt)}</Td>
            <Td>
              <Badge tone={STATE_TONE[t.state]}>{t.state}</Badge>
            </Td>
            <Td className="text-right">
              {t.state === "active" && (
                <Button variant="ghost" size="sm" onClick={() => revoke.mutate({ tokenId: t.id })}>
                  Revoke {t.name}
                </Button>
              )}
            </Td>
          </tr>
        )}
      />
    </div>
  );
}
