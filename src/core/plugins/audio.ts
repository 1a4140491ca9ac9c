// Who plays a "Play audio" action: the robot, where its plugin maps the
// abstract play_audio to one of its actions (the robot truly has a way to
// play a file), or else the wizard's browser, which fetches the study's file
// and plays it beside the participant. The designer shows this choice and the
// runtime follows it, both from here through resolveAction.
import { resolveAction } from "./resolve";
import type { Plugin } from "./types";

export type AudioPlayer = "robot" | "browser";

/** A well-formed play_audio request, only to ask the plugin which way it goes. */
const PROBE = { fileId: "probe", name: "probe.wav", sha256: "0".repeat(64) };

export function audioPlayer(plugin: Plugin | null): AudioPlayer {
  if (!plugin) return "browser";
  return resolveAction(plugin, "play_audio", PROBE).status === "browser" ? "browser" : "robot";
}

/** The choice in the designer's words. */
export function audioPlayerText(player: AudioPlayer): string {
  return player === "robot" ? "played by the robot" : "played by the wizard's browser";
}
