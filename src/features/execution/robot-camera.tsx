"use client";
// What the robot sees (its plugin's camera), for the wizard and those
// watching: shown once a first frame arrives, so a robot without one shows nothing.
// After the trial its last picture stays, marked frozen, so no one takes it for live.
import { Camera } from "lucide-react";
import { useEffect, useState } from "react";
import { Card } from "@/ui/surface";
import type { CameraFrame } from "./use-trial-socket";

const MIME: Record<string, string> = { jpeg: "image/jpeg", jpg: "image/jpeg", png: "image/png" };

/** sensor_msgs/CompressedImage's format is "jpeg", "png" or e.g. "bgr8; jpeg compressed bgr8". */
const mimeOf = (format: string) =>
  MIME[format.trim().toLowerCase()] ?? (format.toLowerCase().includes("png") ? "image/png" : "image/jpeg");

export function RobotCamera({
  onCamera,
  ended,
}: {
  onCamera: (show: (frame: CameraFrame) => void) => () => void;
  ended: boolean;
}) {
  const [src, setSrc] = useState<string | null>(null);
  useEffect(() => onCamera((frame) => setSrc(`data:${mimeOf(frame.format)};base64,${frame.data}`)), [onCamera]);
  if (!src) return null;
  return (
    <Card className="space-y-2 p-4 text-sm">
      <h2 className="flex items-center gap-2 font-semibold">
        <Camera className="h-4 w-4" aria-hidden /> {ended ? "What the robot saw" : "What the robot sees"}
      </h2>
      {ended && (
        <p role="status" data-testid="robot-camera-frozen" className="text-slate-600">
          Frozen: the robot's last picture before the trial ended, not live.
        </p>
      )}
      {/* biome-ignore lint/performance/noImgElement: a live data: URL, a few times a second; nothing for next/image to optimise */}
      <img
        data-testid="robot-camera"
        src={src}
        alt={ended ? "The robot's camera, its last picture (frozen)" : "The robot's camera, live"}
        className={`w-full rounded bg-black ${ended ? "opacity-60 grayscale" : ""}`}
      />
    </Card>
  );
}
