CREATE INDEX "code_events_observer_idx" ON "code_events" USING btree ("observer_id");--> statement-breakpoint
CREATE INDEX "code_events_version_idx" ON "code_events" USING btree ("version_id");