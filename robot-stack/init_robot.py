"""Puts the NAO in a state a Wizard-of-Oz study expects: no autonomous life,
motors awake, standing. Runs once before the bridge starts."""
import os
import sys

import qi


def main() -> int:
    url = f"tcp://{os.environ['NAO_IP']}:{os.environ.get('NAO_PORT', '9559')}"
    app = qi.Application(["hristudio-init", f"--qi-url={url}"])
    try:
        app.start()
    except RuntimeError as error:
        print(f"Cannot reach the robot at {url}: {error}", file=sys.stderr)
        return 1
    session = app.session
    session.service("ALAutonomousLife").setState("disabled")
    session.service("ALMotion").wakeUp()
    session.service("ALRobotPosture").goToPosture("Stand", 0.5)
    print("Robot ready: autonomous life off, awake, standing.")
    return 0


if __name__ == "__main__":
    sys.exit(main())
