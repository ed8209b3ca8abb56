# Replies with NaN, which Python's json.dumps writes although it is not JSON.
import json
import sys

for line in sys.stdin:
    request = json.loads(line)
    print(json.dumps({"id": request["id"], "x": [1.0, float("nan")]}), flush=True)
