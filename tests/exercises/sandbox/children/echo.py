# A well-behaved child: answers every request, telling where it runs and what it was given.
import json
import os
import resource
import sys


def is_open(fd):
    try:
        os.fstat(fd)
        return True
    except OSError:
        return False


for line in sys.stdin:
    request = json.loads(line)
    print(json.dumps({"id": request["id"], "exercise": request["exercise"], "cwd": os.getcwd(),
                      "listing": sorted(os.listdir(".")), "argv": sys.argv, "pid": os.getpid(),
                      "pgid": os.getpgid(0), "core_limit": list(resource.getrlimit(resource.RLIMIT_CORE)),
                      "open_fds": [fd for fd in range(3, 1024) if is_open(fd)]}), flush=True)
