ALTER TABLE "actions" ADD COLUMN "variants" jsonb;--> statement-breakpoint
ALTER TABLE "steps" ADD COLUMN "variants" jsonb;