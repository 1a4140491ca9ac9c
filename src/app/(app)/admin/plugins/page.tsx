import { PluginsPage } from "@/features/admin/plugins-page";
import { requireUser } from "@/app/require-user";

export default async function AdminPluginsPage() {
  const user = await requireUser();
  if (user.role !== "administrator") return <p className="text-slate-600">Only administrators manage robot plugins.</p>;
  return <PluginsPage />;
}
