// Robot plugins in the pure core: the format, loading, abstract actions,
// portability and payloads. No I/O: src/robots reads files and sockets.
export * from "./errors";
export * from "./types";
export { loadPlugin, checkDocument, parseJson } from "./load";
export { parseRepository, parsePluginIndex } from "./repository";
export { ABSTRACT_ACTIONS, abstractAction, type AbstractAction } from "./vocabulary";
export { parseActionType, robotActionType, type ActionType } from "./action-type";
export { validateParameters, withDefaults, type ParameterProblem } from "./parameters";
export { fillTemplate, placeholders, templateProblems } from "./template";
export { parseExpression, MAX_NESTING } from "./expression";
export { dispatchName, fillName, reachableNames, type ReachableNames } from "./topic";
export { TRANSFORMS, transformOf, maxTurnOf, type Transform, type Motion } from "./transforms";
export { actionGoal, type ActionGoal } from "./goal";
export { unavailableActions, unavailableReason, type UnavailableAction } from "./availability";
export { resolveAction, type Resolution } from "./resolve";
export {
  cannotStart,
  eventProblems,
  checkingStart,
  portability,
  type PortableExperiment,
  type PortabilityReport,
  type ActionPortability,
} from "./portability";
export { eventName, eventNamesOf, NO_EVENT_NAMES, type EventNames } from "./event-names";
export { messageTime, sense, UNSENSED, type SenseState, type SenseStep } from "./senses";
export { channelOf, isSshCommand, unreachable, type Channel, type Channels, type Reachable } from "./reach";
export { outgoingFor, type Outgoing } from "./payload";
export { sentOverRos, type Sent } from "./sent";
export { audioPlayer, audioPlayerText, type AudioPlayer } from "./audio";
export { shellCommand, shellWords, quoteWord, type ShellCommand, type ShellWords } from "./shell";
export { httpRequest, type HttpRequest } from "./http";
export { notSeenNotice, pluginChanges, removedNotice, type PluginChange } from "./changes";
export {
  alsoProvided,
  chooseDocument,
  describeDocument,
  effectiveTrust,
  FIRST_PARTY,
  identityKey,
  latestPerSource,
  shortHash,
  type PluginIdentity,
  type ProvidedPlugin,
} from "./identity";
export {
  completionOf,
  expectedDone,
  matchesDone,
  fieldAt,
  valueKey,
  estimatedMs,
  robotTimeOf,
  serviceRefusal,
  isConfirmation,
  type Confirmation,
  type Rule,
} from "./completion";
