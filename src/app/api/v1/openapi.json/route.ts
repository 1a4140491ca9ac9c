import { openApiDocument } from "@/core/analysis/openapi";

// The description holds no study data: anyone may read it, as a client generator would.
export const GET = () => Response.json(openApiDocument());
