"use client";
// The dashboard's "live now": trials running in my studies, one click from
// watching. Asked again every few seconds, so a trial that starts appears.
import { useQuery } from "@tanstack/react-query";
import { Eye, Radio } from "lucide-react";
import Link from "next/link";
import { useTRPC } from "@/lib/trpc";
import { Badge, Card, ROLE_TONE, STATUS_TONE } from "@/ui/surface";
import { clockTime } from "@/ui/clock-time";

const REFRESH_MS = 5000;

const since = (t0: Date | string | null) => (t0 ? `started ${clockTime(t0)}` : "starting");

export function LiveNow() {
  const trpc = useTRPC();
  const live = useQuery({ ...trpc.trials.liveNow.queryOptions(), refetchInterval: REFRESH_MS });
  if (!live.data?.length) return null;
  return (
    <section aria-label="Live now" className="mb-8">
      <h2 className="mb-3 flex items-center gap-2 text-lg font-semibold">
        <Radio className="h-4 w-4 text-red-600" aria-hidden /> Live now
      </h2>
      <ul className="grid gap-3 sm:grid-cols-2 lg:grid-cols-3">
        {live.data.map((t) => (
          <li key={t.trialId}>
            <Card className="flex h-full flex-col gap-2 p-4 text-sm">
              <div className="flex items-start justify-between gap-2">
                <span className="font-semibold">
                  {t.experimentName} · {t.participantCode ?? "no participant"}
                </span>
                <Badge tone={STATUS_TONE[t.status]}>{t.status.replace("_", " ")}</Badge>
              </div>
              <p className="text-slate-600">
                {t.studyTitle} · {t.wizardName ? `wizard ${t.wizardName}` : "no wizard yet"} · {since(t.t0)}
                {t.isRehearsal ? " · rehearsal" : ""}
              </p>
              <div className="mt-auto flex items-center justify-between">
                <Badge tone={ROLE_TONE[t.myRole]}>{t.myRole}</Badge>
                <Link
                  href={`/trials/${t.trialId}`}
                  className="flex items-center gap-1 font-medium text-brand-600 hover:underline"
                >
                  <Eye className="h-4 w-4" aria-hidden /> Watch
                </Link>
              </div>
            </Card>
          </li>
        ))}
      </ul>
    </section>
  );
}
