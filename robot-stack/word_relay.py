"""The robot's speech recogniser as a topic, which naoqi_driver does not offer:
/word_recognized (naoqi_bridge_msgs/WordRecognized), the words ALSpeechRecognition
heard, each with its confidence, as HRIStudio's NAO6 and Pepper plugins declare it.
The vocabulary is SPEECH_VOCABULARY (comma-separated): the words the plugins'
"heard" events listen for, unless a lab sets its own."""
import os

from naoqi_bridge_msgs.msg import WordRecognized
from rclpy.node import Node

from naoqi_node import run

VOCABULARY = "ready,I'm ready,yes,no,stop"


class WordRelay(Node):
    def __init__(self, session):
        super().__init__("hristudio_word_relay")
        self.publisher = self.create_publisher(WordRecognized, "/word_recognized", 10)
        recogniser = session.service("ALSpeechRecognition")
        words = [w.strip() for w in (os.environ.get("SPEECH_VOCABULARY") or VOCABULARY).split(",") if w.strip()]
        # The vocabulary can only change while the recogniser is paused.
        recogniser.pause(True)
        recogniser.setVocabulary(words, False)
        recogniser.pause(False)
        recogniser.subscribe("hristudio_word_relay")
        self.heard = session.service("ALMemory").subscriber("WordRecognized")
        self.heard.signal.connect(self.on_words)

    def on_words(self, value) -> None:
        # ALMemory's WordRecognized: [word, confidence, word, confidence, ...], best first.
        pairs = list(zip(value[0::2], value[1::2]))
        heard = [(str(word), float(confidence)) for word, confidence in pairs if word]
        if heard:
            self.publisher.publish(
                WordRecognized(words=[w for w, _ in heard], confidence_values=[c for _, c in heard])
            )


def main() -> None:
    run("hristudio-word-relay", WordRelay)


if __name__ == "__main__":
    main()
