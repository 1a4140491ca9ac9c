"""Runs one ROS 2 node over a NAOqi session: the relays' shared start and stop.

The robot's address is NAO_IP and NAO_PORT (9559), as naoqi_driver's."""

import os

import qi
import rclpy


def run(name: str, make_node) -> None:
    url = f"tcp://{os.environ['NAO_IP']}:{os.environ.get('NAO_PORT', '9559')}"
    app = qi.Application([name, f"--qi-url={url}"])
    app.start()
    rclpy.init()
    node = make_node(app.session)
    try:
        rclpy.spin(node)
    finally:
        node.destroy_node()
        rclpy.shutdown()
