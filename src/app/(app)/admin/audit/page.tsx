import { AuditLogPage } from "@/features/admin/audit-log-page";
import { requireUser } from "@/app/require-user";

export default async function AdminAuditPage() {
  const user = await requireUser();
  if (user.role !== "administrator") return <p className="text-slate-600">Only administrators read the audit log.</p>;
  return <AuditLogPage />;
}
