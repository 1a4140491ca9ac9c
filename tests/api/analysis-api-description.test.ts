// The OpenAPI description and the route files are two views of one list
// (ENDPOINTS): every route under src/app/api/v1 is described, and every
// described path is a route that answers GET.
import { readdirSync, statSync } from "node:fs";
import { join, relative } from "node:path";
import { describe, expect, it } from "vitest";
import { API_BASE, ENDPOINTS } from "../../src/core/analysis/api";
import { openApiDocument } from "../../src/core/analysis/openapi";

const V1 = join(import.meta.dirname, "..", "..", "src", "app", "api", "v1");

function routeFolders(dir: string): string[] {
  return readdirSync(dir).flatMap((name) => {
    const path = join(dir, name);
    if (statSync(path).isDirectory()) return routeFolders(path);
    return name === "route.ts" ? [relative(V1, dir)] : [];
  });
}

/** A route folder as OpenAPI writes its path: [trialId] → {trialId}. */
const asPath = (folder: string) => `${API_BASE}/${folder.replace(/\[(\w+)\]/g, "{$1}")}`;

const document = openApiDocument();

describe("the analysis API's description", () => {
  it("describes every /api/v1 route, and nothing else", () => {
    expect(Object.keys(document.paths).sort()).toEqual(routeFolders(V1).map(asPath).sort());
  });

  it.each(routeFolders(V1))("%s answers GET", async (folder) => {
    const route = (await import(/* @vite-ignore */ join(V1, folder, "route.ts"))) as Record<string, unknown>;
    expect(typeof route.GET).toBe("function");
  });

  it("names each path's parameters and each table's columns", () => {
    for (const [name, endpoint] of Object.entries(ENDPOINTS)) {
      const { get } = document.paths[`${API_BASE}${endpoint.path}`] as {
        get: {
          operationId: string;
          parameters: Array<{ name: string; in: string }>;
          responses: Record<string, { content?: Record<string, { schema: { items?: { required: string[] } } }> }>;
        };
      };
      expect(get.operationId).toBe(name);
      expect(get.parameters.filter((p) => p.in === "path").map((p) => `{${p.name}}`)).toEqual(
        endpoint.path.match(/\{\w+\}/g) ?? [],
      );
      expect(get.responses["200"]!.content!["application/json"]!.schema.items!.required).toEqual([...endpoint.columns]);
      const refusals = ["400", "401", "403", "404", ...(endpoint.path.includes("{trialId}") ? ["412"] : [])];
      expect(Object.keys(get.responses)).toEqual(["200", ...refusals, "500", "503"]);
    }
  });

  it("says where it is served, under which licence, and each column's real type", () => {
    expect(document.servers).toEqual([{ url: "/", description: "This HRIStudio server" }]);
    expect(document.info.license).toEqual({ name: "MIT", identifier: "MIT" });
    const columns = (name: string) =>
      (
        document.paths[`${API_BASE}${ENDPOINTS[name as keyof typeof ENDPOINTS].path}`] as {
          get: {
            responses: { "200": { content: { "application/json": { schema: { items: { properties: object } } } } } };
          };
        }
      ).get.responses["200"].content["application/json"].schema.items.properties as Record<
        string,
        Record<string, unknown>
      >;
    expect(columns("events").seq).toMatchObject({ type: "integer" });
    expect(columns("events").rel_ms).toMatchObject({ type: ["integer", "null"] });
    expect(columns("events").server_time).toMatchObject({ type: "string", format: "date-time" });
    expect(columns("events").payload).toMatchObject({ type: "string", contentMediaType: "application/json" });
    expect(columns("trials").status).toMatchObject({
      type: "string",
      enum: ["scheduled", "in_progress", "paused", "completed", "aborted"],
    });
    expect(columns("studies").results_hidden).toMatchObject({ type: "boolean" });
    expect(columns("answers").reverse_scored).toMatchObject({ type: ["boolean", "null"] });
    expect(columns("codes").start_ms!.description).toMatch(/\(ms\)$/);
  });

  it("is served at /api/v1/openapi.json as OpenAPI 3.1, without a token", async () => {
    const { GET } = await import("../../src/app/api/v1/openapi.json/route");
    const res = GET();
    expect(res.status).toBe(200);
    const served = (await res.json()) as typeof document;
    expect(served).toEqual(JSON.parse(JSON.stringify(document)));
    expect(served.openapi).toBe("3.1.0");
    expect(served.components.securitySchemes.accessToken).toEqual({ type: "http", scheme: "bearer" });
  });
});
