CREATE TABLE "trial_figures" (
	"trial_id" text PRIMARY KEY NOT NULL,
	"figures_version" integer NOT NULL,
	"version_id" text NOT NULL,
	"last_seq" bigint NOT NULL,
	"figures" json NOT NULL,
	"computed_at" timestamp with time zone DEFAULT now() NOT NULL
);
--> statement-breakpoint
ALTER TABLE "trial_figures" ADD CONSTRAINT "trial_figures_trial_id_trials_id_fk" FOREIGN KEY ("trial_id") REFERENCES "public"."trials"("id") ON DELETE cascade ON UPDATE no action;