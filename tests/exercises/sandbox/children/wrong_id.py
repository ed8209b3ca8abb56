# Replies to every request with the next request's id.
import json
import sys

for line in sys.stdin:
    request = json.loads(line)
    print(json.dumps({"id": request["id"] + 1}), flush=True)
