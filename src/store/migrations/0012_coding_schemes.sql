CREATE TABLE "code_events" (
	"id" text PRIMARY KEY NOT NULL,
	"trial_id" text NOT NULL,
	"observer_id" text,
	"version_id" text NOT NULL,
	"set_id" text NOT NULL,
	"code_id" text NOT NULL,
	"kind" text NOT NULL,
	"start_ms" double precision NOT NULL,
	"end_ms" double precision,
	"modifiers" jsonb DEFAULT '[]'::jsonb NOT NULL,
	"created_at" timestamp with time zone DEFAULT now() NOT NULL,
	"updated_at" timestamp with time zone DEFAULT now() NOT NULL
);
--> statement-breakpoint
CREATE TABLE "coding_scheme_versions" (
	"id" text PRIMARY KEY NOT NULL,
	"scheme_id" text NOT NULL,
	"version" integer NOT NULL,
	"definition" jsonb NOT NULL,
	"hash" text NOT NULL,
	"published_by" text,
	"published_at" timestamp with time zone DEFAULT now() NOT NULL
);
--> statement-breakpoint
CREATE TABLE "coding_schemes" (
	"id" text PRIMARY KEY NOT NULL,
	"study_id" text NOT NULL,
	"name" text NOT NULL,
	"draft" jsonb NOT NULL,
	"created_at" timestamp with time zone DEFAULT now() NOT NULL,
	"updated_at" timestamp with time zone DEFAULT now() NOT NULL
);
--> statement-breakpoint
ALTER TABLE "code_events" ADD CONSTRAINT "code_events_trial_id_trials_id_fk" FOREIGN KEY ("trial_id") REFERENCES "public"."trials"("id") ON DELETE cascade ON UPDATE no action;--> statement-breakpoint
ALTER TABLE "code_events" ADD CONSTRAINT "code_events_observer_id_user_id_fk" FOREIGN KEY ("observer_id") REFERENCES "public"."user"("id") ON DELETE set null ON UPDATE no action;--> statement-breakpoint
ALTER TABLE "code_events" ADD CONSTRAINT "code_events_version_id_coding_scheme_versions_id_fk" FOREIGN KEY ("version_id") REFERENCES "public"."coding_scheme_versions"("id") ON DELETE cascade ON UPDATE no action;--> statement-breakpoint
ALTER TABLE "coding_scheme_versions" ADD CONSTRAINT "coding_scheme_versions_scheme_id_coding_schemes_id_fk" FOREIGN KEY ("scheme_id") REFERENCES "public"."coding_schemes"("id") ON DELETE cascade ON UPDATE no action;--> statement-breakpoint
ALTER TABLE "coding_scheme_versions" ADD CONSTRAINT "coding_scheme_versions_published_by_user_id_fk" FOREIGN KEY ("published_by") REFERENCES "public"."user"("id") ON DELETE set null ON UPDATE no action;--> statement-breakpoint
ALTER TABLE "coding_schemes" ADD CONSTRAINT "coding_schemes_study_id_studies_id_fk" FOREIGN KEY ("study_id") REFERENCES "public"."studies"("id") ON DELETE cascade ON UPDATE no action;--> statement-breakpoint
CREATE INDEX "code_events_trial_idx" ON "code_events" USING btree ("trial_id","start_ms");--> statement-breakpoint
CREATE UNIQUE INDEX "coding_scheme_versions_idx" ON "coding_scheme_versions" USING btree ("scheme_id","version");--> statement-breakpoint
CREATE INDEX "coding_schemes_study_idx" ON "coding_schemes" USING btree ("study_id");