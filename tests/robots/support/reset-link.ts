// Run by Bun, as the runtime is: opens a WatchedSocket to the address given,
// and gives the link up as soon as it is open (watched-socket-reset.test.ts).
import { WatchedSocket } from "../../../src/robots/transports/watched-socket";

const socket = new WatchedSocket(process.argv[2]!, { everyMs: 500, timeoutMs: 1500 }, () => {});
socket.on("open", () => {
  socket.terminate("the robot's bridge stopped answering");
  setTimeout(() => process.exit(0), 200);
});
