// HRIStudio's named payload transforms ("payloadMapping": {"type": "transform",
// "transformFn": ...}). A transform turns an action's parameters into the
// message payload. Only the names listed here load; docs/plugins.md lists them.
import type { JsonObject } from "./types";

type Transform = (parameters: Record<string, unknown>) => JsonObject;

/**
 * NAOqi's text-to-speech reads inline tags: \rspd=N\ sets the speaking rate and
 * \vct=N\ the pitch, both in percent. An emotion is a rate and pitch pair
 * ahead of the text, sent as std_msgs/String {data}. "neutral" or no emotion
 * sends the text alone, so say_with_emotion without an emotion equals say_text.
 */
const EMOTION_VOICE: Record<string, { rate: number; pitch: number }> = {
  happy: { rate: 110, pitch: 115 },
  sad: { rate: 85, pitch: 90 },
};

function transformToEmotionSpeech(parameters: Record<string, unknown>): JsonObject {
  const text = typeof parameters.text === "string" ? parameters.text : "";
  const voice = typeof parameters.emotion === "string" ? EMOTION_VOICE[parameters.emotion] : undefined;
  return { data: voice ? `\\rspd=${voice.rate}\\\\vct=${voice.pitch}\\${text}` : text };
}

export const TRANSFORMS: Record<string, Transform> = { transformToEmotionSpeech };

export function hasTransform(name: string): boolean {
  return Object.hasOwn(TRANSFORMS, name);
}
