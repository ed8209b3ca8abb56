# Answers until a request says "crash"; then says so on stderr and dies of SIGSEGV.
import json
import os
import signal
import sys

for line in sys.stdin:
    request = json.loads(line)
    if request.get("crash"):
        print("about to crash", file=sys.stderr, flush=True)
        os.kill(os.getpid(), signal.SIGSEGV)
    print(json.dumps({"id": request["id"], "pid": os.getpid()}), flush=True)
