// A step as the designer's messages name it: by its name, or by its number when it has none.
import type { DesignStep } from "./types";

export function stepLabel(step: Pick<DesignStep, "name">, index: number): string {
  return step.name.trim() ? `step "${step.name.trim()}"` : `step ${index + 1}`;
}

export function upper(text: string): string {
  return text.charAt(0).toUpperCase() + text.slice(1);
}
