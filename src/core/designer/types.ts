// The designer's vocabulary: the experiment document (declared once, in
// ../protocol/document.ts) and the id source its commands take.
export type { DesignAction, DesignDraft, DesignStep, After } from "../protocol/document";

/** Supplies fresh ids, so the model stays pure and tests stay deterministic. */
export type NewId = () => string;
