import { RobotsPage } from "@/features/admin/robots-page";
import { requireUser } from "@/app/require-user";

export default async function AdminRobotsPage() {
  const user = await requireUser();
  if (user.role !== "administrator") return <p className="text-slate-600">Only administrators manage robots.</p>;
  return <RobotsPage />;
}
