"use client";
// The administrator's pages, one link each; the current one is marked
// for screen readers as well as by colour.
import Link from "next/link";
import { usePathname } from "next/navigation";
import { cn } from "@/ui/cn";

const PAGES = [
  { href: "/admin", label: "Accounts" },
  { href: "/admin/robots", label: "Robots" },
  { href: "/admin/plugins", label: "Robot plugins" },
  { href: "/admin/audit", label: "Audit log" },
];

export function AdminNav() {
  const path = usePathname();
  return (
    <nav aria-label="Administration" className="mb-6 flex gap-1 border-b border-slate-200 text-sm">
      {PAGES.map((p) => (
        <Link
          key={p.href}
          href={p.href}
          aria-current={path === p.href ? "page" : undefined}
          className={cn(
            "-mb-px border-b-2 border-transparent px-4 py-2 font-medium text-slate-600 hover:text-slate-900 focus-visible:outline-none focus-visible:ring-2 focus-visible:ring-brand-500",
            path === p.href && "border-brand-600 text-brand-700",
          )}
        >
          {p.label}
        </Link>
      ))}
    </nav>
  );
}
