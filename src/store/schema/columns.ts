// Column builders the tables share: stable text ids, creation times, snapshots.
import { customType, text, timestamp } from "drizzle-orm/pg-core";
import { type ProtocolSnapshot, readSnapshot } from "../../core/protocol/snapshot";

export const id = () =>
  text("id")
    .primaryKey()
    .$defaultFn(() => crypto.randomUUID());

export const createdAt = () => timestamp("created_at", { withTimezone: true }).notNull().defaultNow();

/**
 * A frozen experiment snapshot (jsonb). Stored bytes stay as they were hashed;
 * reading upgrades older schema versions, so no caller meets an old shape.
 */
export const snapshot = customType<{ data: ProtocolSnapshot; driverData: string }>({
  dataType: () => "jsonb",
  toDriver: (value) => JSON.stringify(value),
  fromDriver: (value) => readSnapshot(typeof value === "string" ? JSON.parse(value) : value),
});
