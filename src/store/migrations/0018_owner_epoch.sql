ALTER TABLE "trials" ADD COLUMN "owner_epoch" integer DEFAULT 0 NOT NULL;--> statement-breakpoint
-- An append of a runtime process that no longer owns the trial fails whole, in its own statement
-- (see appendMany): `moved` is how many of its trials still had the epoch it was sent with.
CREATE FUNCTION hri_fenced(moved bigint, expected integer) RETURNS boolean LANGUAGE plpgsql AS $$
BEGIN
  IF moved <> expected THEN
    RAISE EXCEPTION 'another runtime process took this trial over' USING ERRCODE = 'HR409';
  END IF;
  RETURN true;
END $$;
