// A client offering services (advertise_service), as rosbridge_suite's
// advertise_service, service_response and unadvertise_service capabilities
// do it: another client's call_service reaches the advertiser as a
// call_service with the id "service_request:<name>:<n>" (n counts from 1 per
// advertisement) and the request with every field filled; the advertiser's
// service_response with that id answers the caller. The response's `result`
// is not read (rosbridge fills the response from `values` either way), so a
// response without `values`, or with values not an object, answers nothing:
// the caller waits. Errors go to
// the log only, as everywhere on this server. The newest advertisement of a
// name wins; when an advertisement ends (unadvertise, displaced, the client
// gone) its calls in flight fail, as rosbridge's graceful_shutdown does.
import type { RosGraph } from "./graph";
import { graphName, requireString } from "./fields";
import { lookupType, populateResponse } from "./ros-types";

type Message = Record<string, unknown>;

interface Advertisement {
  /** The name as the client advertised it: what call_service frames to it carry. */
  name: string;
  typeKey: string;
  next: number;
  waiting: Map<string, { answer(values: Message): void; fail(error: Error): void }>;
}

export class AdvertisedServices {
  /** By the name as advertised: service_response and unadvertise_service must spell it the same. */
  private readonly mine = new Map<string, Advertisement>();

  constructor(
    private readonly graph: RosGraph,
    private readonly owner: string,
    private readonly send: (message: Message) => void,
    private readonly log: (text: string) => void,
  ) {}

  advertise(m: Message) {
    const name = requireString(m, "service");
    const type = requireString(m, "type");
    const lookup = lookupType(type, "srv");
    if (!lookup.ok) throw new Error(lookup.reason);
    const ad: Advertisement = { name, typeKey: lookup.key, next: 1, waiting: new Map() };
    const overwrote = this.graph.advertiseService(graphName(name), {
      typeKey: lookup.key,
      owner: this.owner,
      handler: (request) => this.relay(ad, request),
      displaced: () => this.end(ad),
    });
    if (overwrote) this.log(`Duplicate service advertised. Overwriting ${name}.`);
    this.mine.set(name, ad);
    this.log(`Advertised service ${name}`);
  }

  unadvertise(m: Message) {
    if (!("service" in m)) throw new Error("missing service");
    const ad = this.mine.get(m.service as string);
    if (!ad) return this.log(`Service ${String(m.service)} has not been advertised via rosbridge, can't unadvertise.`);
    this.graph.withdrawService(graphName(ad.name), this.owner);
    this.end(ad);
    this.log(`Unadvertised service ${ad.name}`);
  }

  respond(m: Message) {
    const name = requireString(m, "service");
    if ("id" in m && typeof m.id !== "string") throw new Error("id must be a string");
    if ("values" in m && (typeof m.values !== "object" || m.values === null || Array.isArray(m.values)))
      throw new Error("values must be an object");
    if (typeof m.result !== "boolean") throw new Error("result must be a boolean");
    const ad = this.mine.get(name);
    if (!ad) throw new Error(`Service ${name} has not been advertised via rosbridge.`);
    if (!("id" in m)) throw new Error("missing id");
    if (!("values" in m)) throw new Error("missing values");
    const values = populateResponse(ad.typeKey, m.values);
    const waiting = ad.waiting.get(m.id as string);
    if (!waiting) return this.log(`Received service response for unrecognized id: ${String(m.id)}`);
    waiting.answer(values);
  }

  /** The client is gone: everything it offered goes with it. */
  close() {
    for (const ad of this.mine.values()) {
      this.graph.withdrawService(graphName(ad.name), this.owner);
      this.end(ad);
    }
  }

  private relay(ad: Advertisement, request: Message): Promise<Message> {
    const id = `service_request:${ad.name}:${ad.next++}`;
    return new Promise((resolve, reject) => {
      ad.waiting.set(id, {
        answer: (values) => {
          ad.waiting.delete(id);
          resolve(values);
        },
        fail: reject,
      });
      this.send({ op: "call_service", id, service: ad.name, args: request });
    });
  }

  private end(ad: Advertisement) {
    if (this.mine.get(ad.name) === ad) this.mine.delete(ad.name);
    if (!ad.waiting.size) return;
    this.log(
      `Service ${ad.name} was unadvertised with a service call in progress, aborting service calls with request IDs ${[...ad.waiting.keys()].join(", ")}`,
    );
    for (const { fail } of ad.waiting.values()) fail(new Error(`Service ${ad.name} was unadvertised`));
    ad.waiting.clear();
  }
}
