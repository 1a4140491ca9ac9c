"use client";
// The lab's robots: each registered robot's live health (as the runtime last
// wrote it), its plugin, how it is reached and which studies may use it.
import { useMutation, useQuery, useQueryClient } from "@tanstack/react-query";
import { useState } from "react";
import { batteryLow } from "@/core/robots/live-state";
import { useTRPC } from "@/lib/trpc";
import { Button } from "@/ui/button";
import { Problem } from "@/ui/problem";
import { Badge, EmptyState } from "@/ui/surface";
import { Table, Td, Th } from "@/ui/table";
import { RobotForm, type RegisteredRobot } from "./robot-form";
import { clockDateTime } from "@/ui/clock-time";

export function RobotsPage() {
  const trpc = useTRPC();
  const queryClient = useQueryClient();
  // Health changes while the page is open: read again every few seconds.
  const robots = useQuery({ ...trpc.robots.list.queryOptions(), refetchInterval: 5000 });
  const [editing, setEditing] = useState<RegisteredRobot | "new" | null>(null);
  const refresh = () => queryClient.invalidateQueries({ queryKey: trpc.robots.list.queryKey() });
  const remove = useMutation(trpc.robots.remove.mutationOptions({ onSuccess: refresh }));
  const done = () => {
    setEditing(null);
    void refresh();
  };
  return (
    <div className="space-y-6">
      <div className="flex items-center gap-3">
        <h1 className="text-2xl font-semibold">Robots</h1>
        {!editing && (
          <Button className="ml-auto" onClick={() => setEditing("new")}>
            Register a robot
          </Button>
        )}
      </div>
      {editing && (
        <RobotForm
          key={editing === "new" ? "new" : editing.id}
          robot={editing === "new" ? null : editing}
          onDone={done}
        />
      )}
      <Problem error={robots.error ?? remove.error} />
      {robots.data?.length === 0 && (
        <EmptyState title="No robots registered.">Register each robot of the lab so trials can drive it.</EmptyState>
      )}
      {!!robots.data?.length && (
        <Table>
          <thead>
            <tr>
              <Th>Robot</Th>
              <Th>Health</Th>
              <Th>Reached by</Th>
              <Th>Available to</Th>
              <Th className="text-right">Actions</Th>
            </tr>
          </thead>
          <tbody>
            {robots.data.map((r) => (
              <tr key={r.id} data-testid={`robot-${r.name}`}>
                <Td>
                  <div className="font-medium">{r.name}</div>
                  <div className="text-xs text-slate-500">
                    {r.pluginRobotId ?? "any plugin"}
                    {r.simulated && " · simulated"}
                    {r.seeded && " · from the launcher or environment"}
                  </div>
                </Td>
                <Td>
                  <div className="flex flex-wrap gap-1">
                    <Badge tone={r.connected ? "green" : "slate"}>{r.connected ? "connected" : "not connected"}</Badge>
                    {r.inLiveTrial && <Badge tone="blue">in a live trial</Badge>}
                    {r.battery !== null && (
                      <Badge
                        tone={
                          batteryLow({ battery: r.battery, speaking: null, gesture: null, posture: null })
                            ? "red"
                            : "slate"
                        }
                      >
                        battery {r.battery} %
                      </Badge>
                    )}
                  </div>
                  <div className="mt-1 text-xs text-slate-500">
                    {r.lastSeenAt ? `last seen ${clockDateTime(r.lastSeenAt)}` : "never seen by a trial"}
                  </div>
                  {r.problems.map((problem) => (
                    <p key={problem} className="mt-1 max-w-md text-xs text-amber-800" data-testid="robot-problem">
                      {problem}
                    </p>
                  ))}
                </Td>
                <Td className="text-xs text-slate-600">
                  {[r.rosbridgeUrl, r.sshHost && `SSH ${r.sshUser}@${r.sshHost}:${r.sshPort}`, r.httpUrl]
                    .filter(Boolean)
                    .map((way) => (
                      <div key={way as string}>{way}</div>
                    ))}
                  {r.sshSecret && <div>secret from {r.sshSecret}</div>}
                </Td>
                <Td className="text-sm">
                  {r.allStudies
                    ? "every study"
                    : r.studies.length
                      ? r.studies.map((s) => s.title).join(", ")
                      : "no study yet"}
                </Td>
                <Td className="text-right">
                  <Button size="sm" variant="secondary" aria-label={`Change: ${r.name}`} onClick={() => setEditing(r)}>
                    Change
                  </Button>
                  <Button
                    size="sm"
                    variant="ghost"
                    className="ml-2 text-red-800"
                    aria-label={`Remove: ${r.name}`}
                    disabled={remove.isPending || r.inLiveTrial}
                    onClick={() => {
                      if (window.confirm(`Remove ${r.name}? Trials that used it keep their logs.`))
                        remove.mutate({ robotId: r.id });
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
    </div>
  );
}
