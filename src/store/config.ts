// Every setting the server reads from its environment, in one place.
// The README's configuration table lists the same variables.
import { z } from "zod";
import { parseTrustedProxies } from "../core/network/client-address";
import { parseIceServers } from "../core/network/ice-servers";

const flag = z
  .enum(["true", "false", "1", "0", "yes", "no"])
  .transform((v) => v === "true" || v === "1" || v === "yes");

const schema = z.object({
  DATABASE_URL: z.string().url().optional(),
  HRI_DATA_DIR: z.string().default("./data"),
  HOST: z.string().default("127.0.0.1"),
  PORT: z.coerce.number().int().min(0).max(65535).optional(),
  HRI_RUNTIME_PORT: z.coerce.number().int().min(0).max(65535).default(3001),
  // How long the runtime keeps a trial nobody follows open (its robot link and lock), for a wizard who reconnects.
  HRI_TRIAL_IDLE_SECONDS: z.coerce.number().min(0).max(86_400).default(60),
  // Where browsers reach the trial runtime; defaults to HOST and HRI_RUNTIME_PORT.
  HRI_RUNTIME_URL: z.string().url().optional(),
  // The robot's rosbridge WebSocket; unset, the launcher starts the simulated robot and uses it.
  HRI_ROSBRIDGE_URL: z.string().url().optional(),
  // SSH to the robot for NAOqi (qicli) commands such as postures; npm start sets them for the simulated robot.
  // Unset with a real robot, the designer calls those actions not runnable here and trials fail them, with one reason.
  HRI_ROBOT_SSH_HOST: z.string().optional(),
  HRI_ROBOT_SSH_PORT: z.coerce.number().int().min(1).max(65535).default(22),
  HRI_ROBOT_SSH_USER: z.string().default("nao"),
  HRI_ROBOT_SSH_PASSWORD: z.string().optional(),
  HRI_ROBOT_SSH_KEY_FILE: z.string().optional(),
  // The REST API of a robot whose plugin uses the HTTP transport (default: the plugin's httpBaseUrl).
  HRI_ROBOT_HTTP_URL: z.string().url().optional(),
  // Recordings: a folder (default <HRI_DATA_DIR>/media), or MinIO/S3 when HRI_MEDIA_S3_URL is set.
  HRI_MEDIA_DIR: z.string().optional(),
  HRI_MEDIA_S3_URL: z.string().url().optional(),
  HRI_MEDIA_S3_BUCKET: z.string().default("hristudio-media"),
  HRI_MEDIA_S3_ACCESS_KEY: z.string().optional(),
  HRI_MEDIA_S3_SECRET_KEY: z.string().optional(),
  // The largest recording accepted, in MB.
  HRI_MEDIA_MAX_MB: z.coerce.number().int().min(1).default(4096),
  // The simulated robot's rosbridge, set by the launcher when it runs one: the robot page shows it, and
  // replays go to it and nowhere else (never HRI_ROSBRIDGE_URL, which may be a real robot).
  HRI_SIMULATOR_URL: z.string().url().optional(),
  HRI_SIMULATOR_PORT: z.coerce.number().int().min(0).max(65535).default(9090),
  // How long the simulated robots take to say each character: speech is completed when it has been said.
  HRI_SIMULATOR_MS_PER_CHAR: z.coerce.number().min(0).max(1000).default(60),
  // How many simulated robots npm start runs (each a registered robot, for piloting in parallel);
  // default 1 without HRI_ROSBRIDGE_URL, 0 with it.
  HRI_SIMULATED_ROBOTS: z.coerce.number().int().min(0).max(16).optional(),
  BETTER_AUTH_SECRET: z.string().min(32, "must be at least 32 characters").optional(),
  BETTER_AUTH_URL: z.string().url().optional(),
  HRI_ALLOW_SIGNUP: flag.default(false),
  // Sign-in attempts per client address per minute.
  HRI_SIGNIN_PER_MINUTE: z.coerce.number().int().min(1).default(10),
  // Failed sign-ins per account (from any addresses) before it is refused for the rest of the window.
  HRI_SIGNIN_ACCOUNT_FAILURES: z.coerce.number().int().min(1).default(10),
  HRI_SIGNIN_ACCOUNT_WINDOW_MINUTES: z.coerce.number().int().min(1).default(15),
  // Reverse proxies whose X-Forwarded-For is believed (comma-separated IPs or CIDR ranges); none by default.
  HRI_TRUSTED_PROXIES: z
    .string()
    .default("")
    .transform((setting, ctx) => {
      const parsed = parseTrustedProxies(setting);
      if ("error" in parsed) {
        ctx.addIssue({ code: "custom", message: parsed.error });
        return z.NEVER;
      }
      return parsed.ranges;
    }),
  // STUN/TURN servers for the live video between the wizard's and observers' browsers; none on one network.
  HRI_ICE_SERVERS: z
    .string()
    .default("")
    .transform((setting, ctx) => {
      const parsed = parseIceServers(setting);
      if ("error" in parsed) {
        ctx.addIssue({ code: "custom", message: parsed.error });
        return z.NEVER;
      }
      return parsed.servers;
    }),
  HRI_SEED_DEMO: flag.optional(),
  // One password for every demo account (workshops, tests); random when unset.
  HRI_DEMO_PASSWORD: z.string().min(8, "must be at least 8 characters").optional(),
});

export type Config = z.infer<typeof schema>;

export function readConfig(env: NodeJS.ProcessEnv = process.env): Config {
  // An empty variable means "not set", as in most shells' `VAR= command`.
  const set = Object.fromEntries(Object.entries(env).filter(([, v]) => v !== undefined && v !== ""));
  const parsed = schema.safeParse(set);
  if (!parsed.success) {
    const lines = parsed.error.issues.map((i) => `  ${i.path.join(".")}: ${i.message}`);
    throw new Error(`The environment has settings that cannot be used:\n${lines.join("\n")}`);
  }
  return parsed.data;
}
