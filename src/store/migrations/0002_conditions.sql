CREATE TABLE "conditions" (
	"id" text PRIMARY KEY NOT NULL,
	"study_id" text NOT NULL,
	"name" text NOT NULL,
	"description" text DEFAULT '' NOT NULL,
	"experiment_id" text NOT NULL,
	"created_at" timestamp with time zone DEFAULT now() NOT NULL
);
--> statement-breakpoint
ALTER TABLE "participants" ADD COLUMN "condition_id" text;--> statement-breakpoint
ALTER TABLE "participants" ADD COLUMN "condition_order" jsonb;--> statement-breakpoint
ALTER TABLE "participants" ADD COLUMN "assignment" jsonb;--> statement-breakpoint
ALTER TABLE "conditions" ADD CONSTRAINT "conditions_study_id_studies_id_fk" FOREIGN KEY ("study_id") REFERENCES "public"."studies"("id") ON DELETE cascade ON UPDATE no action;--> statement-breakpoint
ALTER TABLE "conditions" ADD CONSTRAINT "conditions_experiment_id_experiments_id_fk" FOREIGN KEY ("experiment_id") REFERENCES "public"."experiments"("id") ON DELETE restrict ON UPDATE no action;--> statement-breakpoint
CREATE UNIQUE INDEX "conditions_study_name_idx" ON "conditions" USING btree ("study_id","name");--> statement-breakpoint
ALTER TABLE "participants" ADD CONSTRAINT "participants_condition_id_conditions_id_fk" FOREIGN KEY ("condition_id") REFERENCES "public"."conditions"("id") ON DELETE set null ON UPDATE no action;