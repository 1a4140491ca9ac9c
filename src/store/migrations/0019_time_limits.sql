ALTER TABLE "actions" ADD COLUMN "time_limit" jsonb;--> statement-breakpoint
ALTER TABLE "steps" ADD COLUMN "time_limit" jsonb;