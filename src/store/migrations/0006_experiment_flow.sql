-- One name for the robot an experiment is designed for: its plugin's robotId.
ALTER TABLE "experiments" RENAME COLUMN "robot_plugin_id" TO "robot_id";--> statement-breakpoint
ALTER TABLE "experiment_versions" RENAME COLUMN "plugin_id" TO "robot_id";--> statement-breakpoint
-- Where a step leads once its actions are done; every existing step went on to the next.
ALTER TABLE "steps" ADD COLUMN "after" jsonb DEFAULT '{"to":"next"}'::jsonb NOT NULL;
