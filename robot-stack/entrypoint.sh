#!/usr/bin/env bash
# Prepares the robot, then runs naoqi_driver, the animation and word relays and rosbridge.
set -euo pipefail
source /opt/ros/humble/setup.bash

python3 /opt/hristudio/init_robot.py

ros2 launch naoqi_driver naoqi_driver.launch.py \
  nao_ip:="${NAO_IP}" nao_port:="${NAO_PORT}" \
  username:="${NAO_USERNAME}" password:="${NAO_PASSWORD}" \
  network_interface:="${NETWORK_INTERFACE}" &

python3 /opt/hristudio/animation_relay.py &
python3 /opt/hristudio/word_relay.py &

exec ros2 launch rosbridge_server rosbridge_websocket_launch.xml \
  address:="${ROSBRIDGE_ADDRESS}" port:="${ROSBRIDGE_PORT}"
