// Shared input pieces, with messages written for people.
import { z } from "zod";

export const id = z.string({ error: "is required" }).min(1, "is required").max(100, "is not a valid id");

export const text = (label: string, max: number) =>
  z
    .string({ error: `${label} is required` })
    .trim()
    .min(1, `${label} must not be empty`)
    .max(max, `${label} must be at most ${max} characters`);
