import { requireUser } from "@/app/require-user";
import { RobotView } from "@/features/robots/robot-view";

export const dynamic = "force-dynamic";

export default async function RobotPage() {
  // The simulator's address is the deployment's: read only for someone signed in (pages render beside the layout).
  await requireUser();
  const url = process.env.HRI_SIMULATOR_URL;
  if (!url)
    return (
      <p className="text-slate-600">
        No simulated robot is running: this installation drives a real robot (HRI_ROSBRIDGE_URL).
      </p>
    );
  return <RobotView url={url} />;
}
