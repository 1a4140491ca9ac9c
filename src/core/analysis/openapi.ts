// The OpenAPI 3.1 description of the analysis API, generated from ENDPOINTS.
import { API_BASE, ENDPOINTS, type Endpoint, OPENAPI_PATH, pathParameters } from "./api";

const error = (description: string) => ({
  description,
  content: {
    "application/json": {
      schema: { type: "object", properties: { error: { type: "string" } }, required: ["error"] },
    },
  },
});

const CELL = { type: ["string", "number", "boolean", "null"] };

function operation(name: string, endpoint: Endpoint) {
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
            "text/csv": { schema: { type: "string" } },
            "application/json": {
              schema: {
                type: "array",
                items: {
                  type: "object",
                  properties: Object.fromEntries(endpoint.columns.map((c) => [c, CELL])),
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
      },
    },
  };
}

export function openApiDocument() {
  const paths: Record<string, unknown> = Object.fromEntries(
    Object.entries(ENDPOINTS).map(([name, endpoint]) => [`${API_BASE}${endpoint.path}`, operation(name, endpoint)]),
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
        "Read-only tidy tables of a study's data for R, Python or any HTTP client. Authenticate with a personal access token (Account → Access tokens): Authorization: Bearer <token>.",
    },
    components: { securitySchemes: { accessToken: { type: "http", scheme: "bearer" } } },
    security: [{ accessToken: [] }],
    paths,
  };
}
