# Starts a reply of 17 MiB that never ends its line.
import sys

for line in sys.stdin:
    sys.stdout.write('{"id": 1, "x": "' + "a" * (17 << 20))
    sys.stdout.flush()
