"""Relays /animation (std_msgs/String, an animation path such as
"animations/Stand/Gestures/Hey_1") to ALAnimationPlayer, which naoqi_driver
does not expose as a topic."""
import os

import qi
import rclpy
from rclpy.node import Node
from std_msgs.msg import String


class AnimationRelay(Node):
    def __init__(self, player):
        super().__init__("hristudio_animation_relay")
        self.player = player
        self.create_subscription(String, "/animation", self.play, 10)

    def play(self, message: String) -> None:
        self.get_logger().info(f"animation: {message.data}")
        # Non-blocking, so a long animation never delays the next message.
        self.player.run(message.data, _async=True)


def main() -> None:
    url = f"tcp://{os.environ['NAO_IP']}:{os.environ.get('NAO_PORT', '9559')}"
    app = qi.Application(["hristudio-animation-relay", f"--qi-url={url}"])
    app.start()
    rclpy.init()
    node = AnimationRelay(app.session.service("ALAnimationPlayer"))
    try:
        rclpy.spin(node)
    finally:
        node.destroy_node()
        rclpy.shutdown()


if __name__ == "__main__":
    main()
