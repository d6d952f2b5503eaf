"""Scout, who brings a cup of tea: a complete K-ICNP robot agent in Python (the scenario of the paper's Table 5)."""
import os

from kicnp_agent import Agent, frame_xml

scout = Agent(
    "scout", os.environ.get("KICNP_TOKEN", ""),              # the token of scout in the gateway's agents.properties
    kind="robot",
    host=os.environ.get("KICNP_HOST", "127.0.0.1"),
    port=int(os.environ.get("KICNP_PORT", "7777")),
    tls_trust=os.environ.get("KICNP_TLS_TRUST"),             # the server's certificate, for a gateway elsewhere
    capabilities=[frame_xml("BringTea", slots={"item": "tea"})],
)


@scout.action("bring")
def bring(command, action):
    """Runs on a thread of its own; 'started' is already reported."""
    item = command.args.get("item", "tea")
    for leg in range(1, 4):
        if action.wait_cancelled(0.1):                       # drive one leg of the way (here: wait)
            return                                           # cancelled: the SDK reports it
        action.progress(leg / 3, "leg %d of 3" % leg)
        scout.sensor("sonar", 1.5 / leg, ttl=2.0)            # metres to the user, for slot conditions
    return "brought a cup of " + item                       # reported as 'ended'; an exception as 'failed'


scout.run_forever()                                          # connects, registers, reconnects; Ctrl-C stops it
