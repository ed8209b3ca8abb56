# Answers every request correctly but with blank lines around the replies: an empty line before,
# a line of spaces and a CRLF line after (a tolerant reader skips them).
import json
import sys

for line in sys.stdin:
    request = json.loads(line)
    sys.stdout.write("\n" + json.dumps({"id": request["id"], "iterations": 13.0}) + "\r\n   \n\r\n")
    sys.stdout.flush()
