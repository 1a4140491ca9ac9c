// Code events as a tidy table, one row per code event: the codes CSV of a
// trial and of the study zip, and the analysis API's "codes" table.
import { tableOf, type Table } from "@/core/analysis/table";
import type { Scheme } from "./scheme";

export const CODE_COLUMNS = [
  "trial_id",
  "observer",
  "scheme",
  "scheme_version",
  "set",
  "code",
  "kind",
  "start_ms",
  "end_ms",
  "modifiers",
] as const;

export type CodeRowInput = {
  trialId: string;
  observer: string;
  scheme: Scheme;
  schemeVersion: number;
  setId: string;
  codeId: string;
  kind: "point" | "state";
  startMs: number;
  endMs: number | null;
  modifiers: string[];
};

/** Sets and codes by their names (as the researcher wrote them), modifiers joined with "; ". */
export function codesTable(codes: CodeRowInput[]): Table {
  return tableOf(
    CODE_COLUMNS,
    codes.map((c) => {
      const set = c.scheme.sets.find((s) => s.id === c.setId);
      const code = set?.codes.find((x) => x.id === c.codeId);
      return {
        trial_id: c.trialId,
        observer: c.observer,
        scheme: c.scheme.name,
        scheme_version: c.schemeVersion,
        set: set?.name ?? c.setId,
        code: code?.name ?? c.codeId,
        kind: c.kind,
        start_ms: c.startMs,
        end_ms: c.endMs,
        modifiers: c.modifiers.join("; "),
      };
    }),
  );
}
