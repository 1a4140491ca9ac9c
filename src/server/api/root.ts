import { accountRouter } from "./routers/account";
import { analysisRouter } from "./routers/analysis";
import { conditionsRouter } from "./routers/conditions";
import { adminRouter } from "./routers/admin";
import { experimentsRouter } from "./routers/experiments";
import { membersRouter } from "./routers/members";
import { participantsRouter } from "./routers/participants";
import { formRouter } from "./routers/form";
import { pluginsRouter } from "./routers/plugins";
import { robotsRouter } from "./routers/robots";
import { questionnairesRouter } from "./routers/questionnaires";
import { codingRouter } from "./routers/coding";
import { recordingsRouter } from "./routers/recordings";
import { audioRouter } from "./routers/audio";
import { sessionsRouter } from "./routers/sessions";
import { studiesRouter } from "./routers/studies";
import { tokensRouter } from "./routers/tokens";
import { trialsRouter } from "./routers/trials";
import { versionsRouter } from "./routers/versions";
import { router } from "./trpc";

export const appRouter = router({
  account: accountRouter,
  studies: studiesRouter,
  members: membersRouter,
  experiments: experimentsRouter,
  versions: versionsRouter,
  participants: participantsRouter,
  conditions: conditionsRouter,
  sessions: sessionsRouter,
  questionnaires: questionnairesRouter,
  coding: codingRouter,
  form: formRouter,
  recordings: recordingsRouter,
  audio: audioRouter,
  plugins: pluginsRouter,
  robots: robotsRouter,
  trials: trialsRouter,
  admin: adminRouter,
  tokens: tokensRouter,
  analysis: analysisRouter,
});

export type AppRouter = typeof appRouter;
