export { decide } from "./decide";
export { apply, fold, initialState } from "./fold";
export { answerOptions, nextUnit } from "./protocol";
export { actionProblems } from "./problems";
export { simulate, type Simulation } from "./simulate";
export * from "./types";
