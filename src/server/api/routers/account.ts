import { guarded, router } from "../trpc";

export const accountRouter = router({
  me: guarded("account.read").query(({ ctx }) => ctx.user),
});
