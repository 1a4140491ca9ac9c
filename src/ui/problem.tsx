// Errors in plain language: the server already phrases them for people.
import { AlertTriangle } from "lucide-react";

interface ApiError {
  message: string;
  data?: { issues?: Array<{ field: string; message: string }> | null; code?: string } | null;
}

export function Problem({ error }: { error: unknown }) {
  if (!error) return null;
  return (
    <div role="alert" className="flex gap-2 rounded-md border border-red-200 bg-red-50 p-3 text-sm text-red-800">
      <AlertTriangle className="mt-0.5 h-4 w-4 shrink-0" aria-hidden />
      <span>{messageOf(error)}</span>
    </div>
  );
}

export function messageOf(error: unknown): string {
  const e = error as ApiError;
  if (e?.data?.code === "UNAUTHORIZED") return "You are signed out. Please sign in again.";
  return e?.message ?? "Something went wrong. Please try again.";
}

/** The message for one field, if the server named it. */
export function fieldError(error: unknown, field: string): string | undefined {
  return (error as ApiError)?.data?.issues?.find((i) => i.field === field)?.message;
}
