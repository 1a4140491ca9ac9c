"""What naoqi_driver does not offer as topics, for HRIStudio:
- /animation (std_msgs/String, an animation path such as
  "animations/Stand/Gestures/Hey_1") played by ALAnimationPlayer, and
  /animation_done ("done: " and the path) once it has run, so a trial's gesture is
  completed when the robot finished it, not when it was sent;
- /speech_done (std_msgs/String, "said: " and the sentence) when ALTextToSpeech has
  finished saying what naoqi_driver passed it from /speech;
- /speech_stop and /animation_stop (std_msgs/Empty): an emergency stop
  silences the robot and ends its gesture at once."""

from rclpy.node import Node
from std_msgs.msg import Empty, String

from naoqi_node import run


class Relay(Node):
    def __init__(self, session):
        super().__init__("hristudio_animation_relay")
        self.player = session.service("ALAnimationPlayer")
        self.speech = session.service("ALTextToSpeech")
        self.playing = set()
        self.animation_done = self.create_publisher(String, "/animation_done", 10)
        self.speech_done = self.create_publisher(String, "/speech_done", 10)
        self.create_subscription(String, "/animation", self.play, 10)
        self.create_subscription(Empty, "/animation_stop", self.stop_animations, 10)
        self.create_subscription(Empty, "/speech_stop", self.stop_speech, 10)
        # ALTextToSpeech says which sentence it is on, and when it is done with it.
        memory = session.service("ALMemory")
        self.sentence = ""
        self.current = memory.subscriber("ALTextToSpeech/CurrentSentence")
        self.current.signal.connect(self.on_sentence)
        self.done = memory.subscriber("ALTextToSpeech/TextDone")
        self.done.signal.connect(self.on_text_done)

    def play(self, message: String) -> None:
        self.get_logger().info(f"animation: {message.data}")
        # Non-blocking, so a long animation never delays the next message.
        future = self.player.run(message.data, _async=True)
        self.playing.add(future)

        def finished(f):
            self.playing.discard(future)
            if not f.hasError() and not f.isCanceled():
                self.animation_done.publish(String(data=f"done: {message.data}"))

        future.addCallback(finished)

    def stop_animations(self, _: Empty) -> None:
        for future in list(self.playing):
            future.cancel()

    def stop_speech(self, _: Empty) -> None:
        self.speech.stopAll()

    def on_sentence(self, sentence) -> None:
        if sentence:
            self.sentence = str(sentence)

    def on_text_done(self, done) -> None:
        if done and self.sentence:
            self.speech_done.publish(String(data=f"said: {self.sentence}"))
            self.sentence = ""


def main() -> None:
    run("hristudio-animation-relay", Relay)


if __name__ == "__main__":
    main()
