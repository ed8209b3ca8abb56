# Starts slowly (a 1 s import, as a heavy library can take), then answers at once, saying how many
# requests it has seen and their ids.
import json
import sys
import time

time.sleep(1.0)
ids = []
for line in sys.stdin:
    request = json.loads(line)
    ids.append(request["id"])
    print(json.dumps({"id": request["id"], "seen": ids}), flush=True)
