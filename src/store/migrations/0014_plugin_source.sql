ALTER TABLE "experiment_versions" ADD COLUMN "plugin_source" text;--> statement-breakpoint
ALTER TABLE "experiments" ADD COLUMN "plugin_source" text;--> statement-breakpoint
-- A version published before this recorded its document's source only in plugin_documents.
UPDATE "experiment_versions" SET "plugin_source" = "plugin_documents"."source" FROM "plugin_documents" WHERE "plugin_documents"."hash" = "experiment_versions"."plugin_hash";
