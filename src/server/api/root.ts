import { router } from "./trpc";
import { studiesRouter } from "./routers/studies";

export const appRouter = router({
  studies: studiesRouter,
});

export type AppRouter = typeof appRouter;
