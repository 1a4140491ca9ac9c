import { UsersPage } from "@/features/admin/users-page";
import { requireUser } from "@/app/require-user";

export default async function AdminPage() {
  const user = await requireUser();
  if (user.role !== "administrator") {
    return <p className="text-slate-600">Only administrators manage accounts.</p>;
  }
  return <UsersPage selfId={user.id} />;
}
