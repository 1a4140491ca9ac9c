CREATE INDEX "conditions_experiment_idx" ON "conditions" USING btree ("experiment_id");--> statement-breakpoint
CREATE INDEX "participants_condition_idx" ON "participants" USING btree ("condition_id");--> statement-breakpoint
CREATE INDEX "trials_experiment_idx" ON "trials" USING btree ("experiment_id");--> statement-breakpoint
CREATE INDEX "trials_version_idx" ON "trials" USING btree ("version_id");--> statement-breakpoint
CREATE INDEX "trials_participant_idx" ON "trials" USING btree ("participant_id");--> statement-breakpoint
CREATE INDEX "trials_wizard_idx" ON "trials" USING btree ("wizard_id");--> statement-breakpoint
CREATE INDEX "sessions_participant_idx" ON "sessions" USING btree ("participant_id");--> statement-breakpoint
CREATE INDEX "sessions_condition_idx" ON "sessions" USING btree ("condition_id");--> statement-breakpoint
CREATE INDEX "sessions_trial_idx" ON "sessions" USING btree ("trial_id");--> statement-breakpoint
CREATE INDEX "questionnaire_links_study_idx" ON "questionnaire_links" USING btree ("study_id");--> statement-breakpoint
CREATE INDEX "questionnaire_links_version_idx" ON "questionnaire_links" USING btree ("version_id");--> statement-breakpoint
CREATE INDEX "questionnaire_links_participant_idx" ON "questionnaire_links" USING btree ("participant_id");--> statement-breakpoint
CREATE INDEX "questionnaire_links_trial_idx" ON "questionnaire_links" USING btree ("trial_id");--> statement-breakpoint
CREATE INDEX "questionnaires_study_idx" ON "questionnaires" USING btree ("study_id");