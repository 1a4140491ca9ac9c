export * from "./auth";
export * from "./experiments";
export * from "./plugins";
export * from "./studies";
export * from "./trials";
export * from "./sessions";
export * from "./questionnaires";
export * from "./security";
