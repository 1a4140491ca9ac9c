import { defineConfig } from "drizzle-kit";

export default defineConfig({
  dialect: "postgresql",
  schema: "./src/store/schema/index.ts",
  out: "./src/store/migrations",
  dbCredentials: { url: process.env.DATABASE_URL ?? "postgres://localhost/hristudio" },
});
