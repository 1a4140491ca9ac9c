// The OpenAPI 3.1 description of the analysis API, generated from ENDPOINTS,
// each column typed from its declaration (columns.ts).
import { API_BASE, ENDPOINTS, type Endpoint, type EndpointName, OPENAPI_PATH, pathParameters } from "./api";
import { columnSchema, TABLE_COLUMNS } from "./columns";

const error = (description: string) => ({
  description,
  content: {
    "application/json": {
      schema: { type: "object", properties: { error: { type: "string" } }, required: ["error"] },
    },
  },
});

/** The endpoint's table: one trial's events are the events table. */
const tableOf = (name: EndpointName) => TABLE_COLUMNS[name === "trialEvents" ? "events" : name];

function operation(name: EndpointName, endpoint: Endpoint) {
  const columns = tableOf(name) as Record<string, Parameters<typeof columnSchema>[0]>;
  return {
    get: {
      operationId: name,
      summary: endpoint.summary,
      description: endpoint.description,
      security: [{ accessToken: [] }],
      parameters: [
        ...pathParameters(endpoint.path).map((p) => ({
          name: p,
          in: "path",
          required: true,
          schema: { type: "string" },
        })),
        {
          name: "format",
          in: "query",
          required: false,
          description: "csv (the default) or json; without it, Accept: application/json chooses JSON.",
          schema: { type: "string", enum: ["csv", "json"] },
        },
      ],
      responses: {
        "200": {
          description: `A table with the columns ${endpoint.columns.join(", ")}.`,
          content: {
            // For scripts: text as it was typed, no spreadsheet formula guard (the app's downloads keep theirs).
            "text/csv": { schema: { type: "string" } },
            "application/json": {
              schema: {
                type: "array",
                items: {
                  type: "object",
                  properties: Object.fromEntries(endpoint.columns.map((c) => [c, columnSchema(columns[c]!)])),
                  required: [...endpoint.columns],
                },
              },
            },
          },
        },
        "400": error("A parameter is wrong (the message says which)."),
        "401": error("No token, or a token that is unknown, expired or revoked, or whose owner's account is disabled."),
        "403": error("The token's owner may not read this study's data now (their role, or the study's blinding)."),
        "404": error("No such row, or it belongs to a study outside the token's scope or its owner's studies."),
        // A study's tables leave a withdrawn participant out; one trial of theirs is refused by name.
        ...(pathParameters(endpoint.path).includes("trialId")
          ? { "412": error("The trial's participant withdrew from the study: their data is excluded.") }
          : {}),
        "500": error(
          "An unexpected failure: the message gives a reference to quote; the details are in the server's log.",
        ),
        "503": error("The database cannot be reached now: try again later."),
      },
    },
  };
}

export function openApiDocument() {
  const paths: Record<string, unknown> = Object.fromEntries(
    Object.entries(ENDPOINTS).map(([name, endpoint]) => [
      `${API_BASE}${endpoint.path}`,
      operation(name as EndpointName, endpoint),
    ]),
  );
  paths[`${API_BASE}${OPENAPI_PATH}`] = {
    get: {
      operationId: "openapi",
      summary: "This description",
      security: [],
      responses: { "200": { description: "The OpenAPI 3.1 document.", content: { "application/json": {} } } },
    },
  };
  return {
    openapi: "3.1.0",
    info: {
      title: "HRIStudio analysis API",
      // The version of this description; the path says the API's (v1), which changes only by breaking.
      version: "1.0.0",
      description:
        "Read-only tidy tables of a study's data for R, Python or any HTTP client. Authenticate with a personal access token (Account → Access tokens): Authorization: Bearer <token>. CSV is written for scripts: text exactly as it was typed, with no spreadsheet formula guard.",
      license: { name: "MIT", identifier: "MIT" },
    },
    // Relative: the server this description is fetched from (OpenAPI 3.1 resolves it against the document's address).
    servers: [{ url: "/", description: "This HRIStudio server" }],
    components: { securitySchemes: { accessToken: { type: "http", scheme: "bearer" } } },
    security: [{ accessToken: [] }],
    paths,
  };
}
