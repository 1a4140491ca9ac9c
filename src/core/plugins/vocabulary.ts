// The abstract actions experiments use so one design runs on any robot. Each
// plugin maps what it supports ("abstract") and lists what it cannot do
// ("unsupported"). "pause" is carried out by the trial runtime itself (it is
// also one of the engine's control blocks), so every robot supports it.
import type { ParameterSchema } from "./types";

export interface AbstractAction {
  id: string;
  name: string;
  parameterSchema: ParameterSchema;
  /** Performed by the trial runtime, never sent to a robot. */
  runtime?: true;
  /** Carried out by the wizard's browser on a robot whose plugin does not map it. */
  browserFallback?: true;
}

const none: ParameterSchema = { type: "object", properties: {}, additionalProperties: false };

export const ABSTRACT_ACTIONS: AbstractAction[] = [
  {
    id: "say",
    name: "Say",
    parameterSchema: {
      type: "object",
      properties: { text: { type: "string", title: "Text", minLength: 1 } },
      required: ["text"],
      additionalProperties: false,
    },
  },
  { id: "wave", name: "Wave", parameterSchema: none },
  { id: "nod", name: "Nod", parameterSchema: none },
  { id: "head_shake", name: "Head shake", parameterSchema: none },
  { id: "look_down", name: "Look down", parameterSchema: none },
  {
    id: "pause",
    name: "Pause",
    runtime: true,
    parameterSchema: {
      type: "object",
      properties: { seconds: { type: "number", title: "Seconds", minimum: 0, maximum: 3600 } },
      required: ["seconds"],
      additionalProperties: false,
    },
  },
  {
    id: "posture",
    name: "Posture",
    parameterSchema: {
      type: "object",
      properties: { posture: { type: "string", title: "Posture", enum: ["stand", "sit", "crouch", "rest"] } },
      required: ["posture"],
      additionalProperties: false,
    },
  },
  {
    id: "play_animation",
    name: "Play animation",
    parameterSchema: {
      type: "object",
      properties: { name: { type: "string", title: "Animation name", minLength: 1 } },
      required: ["name"],
      additionalProperties: false,
    },
  },
  {
    id: "move",
    name: "Move",
    parameterSchema: {
      type: "object",
      properties: {
        direction: { type: "string", title: "Direction", enum: ["forward", "backward", "turn_left", "turn_right"] },
        speed: { type: "number", title: "Speed (m/s)", default: 0.1, minimum: 0, maximum: 2 },
      },
      required: ["direction"],
      additionalProperties: false,
    },
  },
  { id: "stop", name: "Stop", parameterSchema: none },
  {
    // The file is one of the study's audio files; its name and content hash
    // travel with the id, so a published version pins the exact sound.
    id: "play_audio",
    name: "Play audio",
    browserFallback: true,
    parameterSchema: {
      type: "object",
      properties: {
        fileId: { type: "string", title: "Audio file", minLength: 1, maxLength: 100 },
        name: { type: "string", title: "File name", minLength: 1, maxLength: 255 },
        sha256: { type: "string", title: "SHA-256", pattern: "^[0-9a-f]{64}$" },
        durationMs: { type: "number", title: "Length (ms)", minimum: 0 },
      },
      required: ["fileId", "name", "sha256"],
      additionalProperties: false,
    },
  },
];

export function abstractAction(id: string): AbstractAction | undefined {
  return ABSTRACT_ACTIONS.find((a) => a.id === id);
}
