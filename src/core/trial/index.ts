export { decide, decideReports, type RobotReportCommand } from "./decide";
export { apply, applyAll, applyInPlace, fold, initialState } from "./fold";
export { answerOptions, nextUnit } from "./protocol";
export { actionProblems } from "./problems";
export { simulate, type Simulation } from "./simulate";
export * from "./types";
export { type Rehearsal, type RehearsedStep, rehearse } from "./rehearse";
export { type FlowEdge, flowEdges } from "./graph";
export { pathTaken, type Upcoming, upcoming } from "./path";
