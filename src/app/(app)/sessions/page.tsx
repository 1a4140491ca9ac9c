import { MySessionsPage } from "@/features/sessions/my-sessions-page";

export default function Page() {
  return <MySessionsPage />;
}
