import type { ReactNode } from "react";
import { AdminNav } from "@/features/admin/admin-nav";
import { requireUser } from "@/app/require-user";

export default async function AdminLayout({ children }: { children: ReactNode }) {
  const user = await requireUser();
  return (
    <>
      {user.role === "administrator" && <AdminNav />}
      {children}
    </>
  );
}
