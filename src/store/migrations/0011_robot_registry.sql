CREATE TABLE "robot_studies" (
	"robot_id" text NOT NULL,
	"study_id" text NOT NULL,
	CONSTRAINT "robot_studies_robot_id_study_id_pk" PRIMARY KEY("robot_id","study_id")
);
--> statement-breakpoint
CREATE TABLE "robots" (
	"id" text PRIMARY KEY NOT NULL,
	"name" text NOT NULL,
	"plugin_robot_id" text,
	"simulated" boolean DEFAULT false NOT NULL,
	"rosbridge_url" text,
	"ssh_host" text,
	"ssh_port" integer DEFAULT 22 NOT NULL,
	"ssh_user" text,
	"ssh_secret" text,
	"http_url" text,
	"all_studies" boolean DEFAULT false NOT NULL,
	"seeded_from" text,
	"connected" boolean DEFAULT false NOT NULL,
	"battery" double precision,
	"last_seen_at" timestamp with time zone,
	"created_at" timestamp with time zone DEFAULT now() NOT NULL,
	CONSTRAINT "robots_name_unique" UNIQUE("name"),
	CONSTRAINT "robots_seeded_from_unique" UNIQUE("seeded_from")
);
--> statement-breakpoint
ALTER TABLE "trials" ADD COLUMN "assigned_robot_id" text;--> statement-breakpoint
ALTER TABLE "robot_studies" ADD CONSTRAINT "robot_studies_robot_id_robots_id_fk" FOREIGN KEY ("robot_id") REFERENCES "public"."robots"("id") ON DELETE cascade ON UPDATE no action;--> statement-breakpoint
ALTER TABLE "robot_studies" ADD CONSTRAINT "robot_studies_study_id_studies_id_fk" FOREIGN KEY ("study_id") REFERENCES "public"."studies"("id") ON DELETE cascade ON UPDATE no action;--> statement-breakpoint
CREATE INDEX "robot_studies_study_idx" ON "robot_studies" USING btree ("study_id");--> statement-breakpoint
ALTER TABLE "trials" ADD CONSTRAINT "trials_assigned_robot_id_robots_id_fk" FOREIGN KEY ("assigned_robot_id") REFERENCES "public"."robots"("id") ON DELETE set null ON UPDATE no action;--> statement-breakpoint
CREATE INDEX "trials_robot_idx" ON "trials" USING btree ("assigned_robot_id");--> statement-breakpoint
CREATE UNIQUE INDEX "trials_live_robot_idx" ON "trials" USING btree ("assigned_robot_id") WHERE "trials"."status" in ('in_progress', 'paused');