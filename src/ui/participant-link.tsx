"use client";
// A link a participant opens on their own device: its QR code for a tablet's
// camera, the address to copy, and "open on this device" for a tablet handed
// over with the page already open.
import { ExternalLink } from "lucide-react";
import { Button } from "./button";
import { Problem } from "./problem";
import { qrPath } from "./qr-code";
import { useCopy } from "./use-copy";

export function ParticipantLink({ url, testId }: { url: string; testId: string }) {
  const { size, path } = qrPath(url);
  const { copied, copyError, copy } = useCopy();
  return (
    <div className="space-y-2">
      <svg
        role="img"
        aria-label="QR code of the link: point the participant's device's camera at it"
        viewBox={`-2 -2 ${size + 4} ${size + 4}`}
        className="h-40 w-40 bg-white"
        shapeRendering="crispEdges"
        data-testid="link-qr"
      >
        <path d={path} fill="black" />
      </svg>
      <p className="break-all rounded-md bg-slate-50 p-2 font-mono text-xs" data-testid={testId}>
        {url}
      </p>
      <div className="flex flex-wrap items-center gap-3">
        <Button size="sm" variant="secondary" onClick={() => void copy("the link", url)}>
          Copy link
        </Button>
        <a
          href={url}
          target="_blank"
          rel="noreferrer"
          className="inline-flex items-center gap-1 text-sm font-medium text-brand-700 hover:underline"
        >
          <ExternalLink className="h-3.5 w-3.5" aria-hidden /> Open on this device
        </a>
        {copied && (
          <span role="status" className="text-sm text-emerald-800">
            Copied {copied}.
          </span>
        )}
      </div>
      <Problem error={copyError} />
    </div>
  );
}
