import { requireUser } from "@/app/require-user";
import { StudyList } from "@/features/studies/study-list";

export default async function StudiesPage() {
  const user = await requireUser();
  return <StudyList systemRole={user.role} />;
}
