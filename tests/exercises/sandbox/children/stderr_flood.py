# Writes 1,000,000 bytes to stderr (10,000 lines of 99 x's) before each reply.
import json
import sys

for line in sys.stdin:
    request = json.loads(line)
    sys.stderr.write(("x" * 99 + "\n") * 10000)
    sys.stderr.flush()
    print(json.dumps({"id": request["id"]}), flush=True)
