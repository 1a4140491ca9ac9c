ALTER TABLE "media_recordings" ADD COLUMN "last_part_at" timestamp with time zone;--> statement-breakpoint
ALTER TABLE "media_recordings" ADD COLUMN "cut_off" boolean DEFAULT false NOT NULL;--> statement-breakpoint
CREATE INDEX "media_recordings_open_idx" ON "media_recordings" USING btree ("created_at") WHERE "media_recordings"."status" = 'recording';