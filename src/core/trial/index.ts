export { decide } from "./decide";
export { apply, fold, initialState } from "./fold";
export { answerOptions, nextUnit } from "./protocol";
export * from "./types";
