import type { ReactNode } from "react";
import { requireUser } from "@/app/require-user";
import { TopBar } from "@/features/shell/top-bar";

export const dynamic = "force-dynamic";

export default async function AppLayout({ children }: { children: ReactNode }) {
  const user = await requireUser();
  return (
    <div className="min-h-full">
      <TopBar user={user} />
      <main className="mx-auto max-w-6xl px-4 py-8 sm:px-6">{children}</main>
    </div>
  );
}
