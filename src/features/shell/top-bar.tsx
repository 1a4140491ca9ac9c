"use client";
import Link from "next/link";
import { useRouter } from "next/navigation";
import type { SignedInUser } from "@/server/api/trpc";
import { authClient } from "@/lib/auth-client";
import { Button } from "@/ui/button";
import { Badge, ROLE_TONE } from "@/ui/surface";

export function TopBar({ user }: { user: SignedInUser }) {
  const router = useRouter();
  // On a phone the bar wraps onto a second line rather than pushing the page wider than the screen.
  return (
    <header className="border-b border-slate-200 bg-white">
      <div className="mx-auto flex min-h-14 max-w-6xl flex-wrap items-center gap-x-6 gap-y-2 px-4 py-2 sm:px-6">
        <Link href="/studies" className="text-lg font-semibold text-brand-700">
          HRIStudio
        </Link>
        <nav className="flex flex-wrap gap-x-4 gap-y-1 text-sm" aria-label="Main">
          <Link href="/studies" className="text-slate-700 hover:text-slate-950">
            Studies
          </Link>
          <Link href="/sessions" className="text-slate-700 hover:text-slate-950">
            My sessions
          </Link>
          <Link href="/robot" className="text-slate-700 hover:text-slate-950">
            Robot
          </Link>
          {user.role === "administrator" && (
            <Link href="/admin" className="text-slate-700 hover:text-slate-950">
              Admin
            </Link>
          )}
        </nav>
        <div className="ml-auto flex flex-wrap items-center gap-3 text-sm">
          <span data-testid="current-user">{user.name}</span>
          <Badge tone={ROLE_TONE[user.role]}>{user.role}</Badge>
          <Link href="/account/tokens" className="text-slate-700 hover:text-slate-950">
            Access tokens
          </Link>
          <Button
            variant="ghost"
            size="sm"
            onClick={async () => {
              await authClient.signOut();
              router.replace("/sign-in");
              router.refresh();
            }}
          >
            Sign out
          </Button>
        </div>
      </div>
    </header>
  );
}
