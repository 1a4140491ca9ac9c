CREATE TABLE "plugin_documents" (
	"hash" text PRIMARY KEY NOT NULL,
	"robot_id" text NOT NULL,
	"version" text NOT NULL,
	"source" text NOT NULL,
	"definition" jsonb NOT NULL,
	"created_at" timestamp with time zone DEFAULT now() NOT NULL
);
--> statement-breakpoint
CREATE TABLE "sign_in_throttle" (
	"key" text PRIMARY KEY NOT NULL,
	"failures" integer DEFAULT 0 NOT NULL,
	"window_started_at" timestamp with time zone DEFAULT now() NOT NULL
);
--> statement-breakpoint
CREATE TABLE "socket_token_uses" (
	"token_id" text PRIMARY KEY NOT NULL,
	"user_id" text NOT NULL,
	"trial_id" text NOT NULL,
	"used_at" timestamp with time zone DEFAULT now() NOT NULL,
	"expires_at" timestamp with time zone NOT NULL
);
--> statement-breakpoint
DROP INDEX "installed_plugins_robot_version_idx";--> statement-breakpoint
ALTER TABLE "experiment_versions" ADD COLUMN "plugin_hash" text;--> statement-breakpoint
CREATE UNIQUE INDEX "installed_plugins_repository_robot_version_idx" ON "installed_plugins" USING btree ("repository_id","robot_id","version");--> statement-breakpoint
-- Open trial sockets learn of every change to who may do what, whichever code path made it.
CREATE FUNCTION hri_access_changed() RETURNS trigger LANGUAGE plpgsql AS $$
DECLARE
  row_data record;
BEGIN
  IF TG_OP = 'DELETE' THEN row_data := OLD; ELSE row_data := NEW; END IF;
  IF TG_TABLE_NAME = 'study_members' THEN
    PERFORM pg_notify('hri_access', json_build_object('studyId', row_data.study_id, 'userId', row_data.user_id)::text);
  ELSIF TG_TABLE_NAME = 'studies' THEN
    PERFORM pg_notify('hri_access', json_build_object('studyId', row_data.id)::text);
  ELSIF TG_TABLE_NAME = 'trials' THEN
    PERFORM pg_notify('hri_access', json_build_object('trialId', row_data.id)::text);
  ELSIF TG_TABLE_NAME = 'user' THEN
    PERFORM pg_notify('hri_access', json_build_object('userId', row_data.id)::text);
  END IF;
  RETURN NULL;
END $$;
--> statement-breakpoint
CREATE TRIGGER study_members_access AFTER INSERT OR UPDATE OR DELETE ON "study_members" FOR EACH ROW EXECUTE FUNCTION hri_access_changed();
--> statement-breakpoint
CREATE TRIGGER studies_access AFTER UPDATE OF "settings", "status" OR DELETE ON "studies" FOR EACH ROW EXECUTE FUNCTION hri_access_changed();
--> statement-breakpoint
CREATE TRIGGER trials_access AFTER UPDATE OF "wizard_id" ON "trials" FOR EACH ROW EXECUTE FUNCTION hri_access_changed();
--> statement-breakpoint
CREATE TRIGGER user_access AFTER UPDATE OF "role", "disabled" OR DELETE ON "user" FOR EACH ROW EXECUTE FUNCTION hri_access_changed();
