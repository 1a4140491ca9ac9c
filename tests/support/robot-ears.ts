// Listens on the simulated robot's speech topic with the real roslib client:
// what a test reads here is what the robot was asked to say, in order.
import * as ROSLIB from "roslib";

export async function listenToSpeech(url: string, topic = "/speech") {
  const ros = new ROSLIB.Ros({ url });
  await new Promise<void>((ok, fail) => {
    ros.on("connection", () => ok());
    ros.on("error", (e) => fail(new Error(`Could not reach the simulated robot at ${url}: ${String(e)}`)));
  });
  const heard: string[] = [];
  const speech = new ROSLIB.Topic<{ data: string }>({ ros, name: topic, messageType: "std_msgs/msg/String" });
  speech.subscribe((m) => heard.push(m.data));
  return {
    heard,
    /** Everything heard so far, and a fresh start for what follows. */
    take(): string[] {
      return heard.splice(0);
    },
    close() {
      speech.unsubscribe();
      ros.close();
    },
  };
}
