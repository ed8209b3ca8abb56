# Starts `sleep 1000` in the background (in the same process group) and tells its pid; answers the
# next request only when asked to; exits at end of input, leaving the sleep behind.
import json
import subprocess
import sys
import time

sleeper = subprocess.Popen(["sleep", "1000"])
for line in sys.stdin:
    request = json.loads(line)
    if request.get("hang"):
        time.sleep(1000)
    print(json.dumps({"id": request["id"], "grandchild": sleeper.pid}), flush=True)
