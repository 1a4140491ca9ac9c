// call_service as the recorded server answers it (transcripts 04, 05): the
// only op with an error reply on the wire. The "service" field echoes the
// request verbatim; an id is echoed when given (or taken from a legacy
// "name#id"); a failure has result false and values a string. Calls run
// concurrently, so a slow service does not hold up the next call: match
// responses by id. The "timeout" field is ignored, as on the real server.
import { graphName } from "./fields";
import type { RosGraph } from "./graph";
import { populateRequest, requestFields } from "./ros-types";

type Message = Record<string, unknown>;

export class ServiceCalls {
  constructor(
    private readonly graph: RosGraph,
    private readonly send: (message: Message) => void,
    private readonly log: (text: string) => void,
  ) {}

  call(m: Message) {
    if (!("service" in m)) throw new Error("missing service");
    if (typeof m.service !== "string") throw new Error("service must be a string");
    const hash = m.service.indexOf("#");
    const id = m.id !== undefined ? m.id : hash >= 0 ? m.service.slice(hash + 1) : undefined;
    const bare = hash >= 0 ? m.service.slice(0, hash) : m.service;
    const name = graphName(bare);
    const respond = (values: unknown, result: boolean) =>
      this.send({ op: "service_response", service: m.service, values, result, ...(id !== undefined ? { id } : {}) });
    const service = this.graph.services.get(name);
    if (!service) return respond(`Service ${name} does not exist`, false);
    let request: Message;
    try {
      request = populateRequest(service.typeKey, this.args(service.typeKey, m.args));
    } catch (error) {
      return respond((error as Error).message, false);
    }
    Promise.resolve()
      .then(() => service.handler(request))
      .then(
        (values) => respond(values, true),
        (error: Error) => {
          this.log(`service ${name} failed: ${error.message}`);
          respond(`service [${name}] responded with an error: error processing request: ${error.message}`, false);
        },
      );
  }

  /** A list fills fields in order (extra items ignored); anything but an object or list means no args. */
  private args(typeKey: string, args: unknown): unknown {
    if (Array.isArray(args))
      return Object.fromEntries(
        requestFields(typeKey)
          .slice(0, args.length)
          .map((f, i) => [f, args[i]]),
      );
    if (args && typeof args === "object") return args;
    return {};
  }
}
