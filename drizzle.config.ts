import { defineConfig } from "drizzle-kit";

export default defineConfig({
  dialect: "postgresql",
  schema: "./src/data/schema/index.ts",
  out: "./src/data/migrations",
  dbCredentials: { url: process.env.DATABASE_URL ?? "postgres://localhost/hristudio" },
});
