// rosbridge reads each connection's text as one stream (transcript 07): it
// appends the frame to a buffer and tries to parse the whole buffer; if that
// fails it looks for the first "{...}" slice that parses and has an "op",
// drops everything before it, and keeps the rest for later. So a request
// split across frames is reassembled, two requests in a frame both run, a
// truncated one is lost, and garbage around a request is ignored.

import { parsePythonJson } from "../../core/robots/python-json";

export class IncomingStream {
  private buffer = "";

  /** Appends text; returns the next message found, or undefined. Call with "" to drain. */
  next(text: string): { message: unknown } | undefined {
    this.buffer += text;
    if (!this.buffer) return undefined;
    try {
      const message: unknown = parsePythonJson(this.buffer);
      this.buffer = "";
      return { message };
    } catch {
      return this.search();
    }
  }

  get pending(): boolean {
    return this.buffer.length > 0;
  }

  private search(): { message: unknown } | undefined {
    const text = this.buffer;
    const closings: number[] = [];
    for (let i = text.indexOf("}"); i >= 0; i = text.indexOf("}", i + 1)) closings.push(i);
    for (let start = text.indexOf("{"); start >= 0; start = text.indexOf("{", start + 1)) {
      for (const end of closings) {
        if (end < start) continue;
        let candidate: unknown;
        try {
          candidate = parsePythonJson(text.slice(start, end + 1));
        } catch {
          continue;
        }
        if ((candidate as Record<string, unknown>).op != null) {
          this.buffer = text.slice(end + 1);
          return { message: candidate };
        }
      }
    }
    return undefined;
  }
}
