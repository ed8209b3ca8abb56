# Answers the first request, then exits (code 0) without waiting for the next.
import json
import sys

request = json.loads(sys.stdin.readline())
print(json.dumps({"id": request["id"]}), flush=True)
sys.exit(0)
