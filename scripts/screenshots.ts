// `npm run screenshots`: refreshes the screenshots the docs show (docs/screenshots). The browser tests
// take them, but a test run keeps its own under .tmp and leaves the committed ones alone; this runs
// the browser tests (or the files named) with HRI_REFRESH_SCREENSHOTS=1, as `npm test` runs them.
import { REFRESH_SCREENSHOTS } from "../tests/support/browser";

process.env[REFRESH_SCREENSHOTS] = "1";
if (process.argv.length <= 2) process.argv.push("tests/e2e");
await import("./test");
