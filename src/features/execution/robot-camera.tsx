"use client";
// What the robot sees (its plugin's camera), for the wizard and those
// watching: shown once a first frame arrives, so a robot without one shows nothing.
// After the trial its last picture stays, marked frozen, so no one takes it for live.
// Hidden (here, or with the whole tab), the page stops receiving it: an
// observer who does not look costs the robot's network nothing.
import { Camera, Eye, EyeOff } from "lucide-react";
import { useEffect, useState } from "react";
import { Button } from "@/ui/button";
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
  // Shown once the robot sent a picture: a robot without a camera shows nothing at all.
  const [seen, setSeen] = useState(false);
  const [hidden, setHidden] = useState(false);
  useEffect(() => {
    if (hidden) return;
    return onCamera((frame) => {
      setSeen(true);
      setSrc(`data:${mimeOf(frame.format)};base64,${frame.data}`);
    });
  }, [onCamera, hidden]);
  // Hiding drops the picture too, so an old one is never shown later as live, or as the last.
  const toggle = () => {
    setHidden((h) => !h);
    setSrc(null);
  };
  if (!seen) return null;
  return (
    <Card className="space-y-2 p-4 text-sm">
      <h2 className="flex items-center gap-2 font-semibold">
        <Camera className="h-4 w-4" aria-hidden /> {ended ? "What the robot saw" : "What the robot sees"}
        {!ended && (
          <Button
            size="sm"
            variant="secondary"
            className="ml-auto"
            aria-label={hidden ? "Show the robot's camera" : "Hide the robot's camera"}
            onClick={toggle}
          >
            {hidden ? <Eye className="h-3.5 w-3.5" aria-hidden /> : <EyeOff className="h-3.5 w-3.5" aria-hidden />}
            {hidden ? "Show" : "Hide"}
          </Button>
        )}
      </h2>
      {hidden && (
        <p role="status" data-testid="robot-camera-hidden" className="text-slate-600">
          {ended
            ? "Hidden when the trial ended: no last picture to show."
            : "Hidden: this page receives no pictures from the robot until you show them again."}
        </p>
      )}
      {ended && src && (
        <p role="status" data-testid="robot-camera-frozen" className="text-slate-600">
          Frozen: the robot's last picture before the trial ended, not live.
        </p>
      )}
      {src && (
        // biome-ignore lint/performance/noImgElement: a live data: URL, a few times a second; nothing for next/image to optimise
        <img
          data-testid="robot-camera"
          src={src}
          alt={ended ? "The robot's camera, its last picture (frozen)" : "The robot's camera, live"}
          className={`w-full rounded bg-black ${ended ? "opacity-60 grayscale" : ""}`}
        />
      )}
    </Card>
  );
}
