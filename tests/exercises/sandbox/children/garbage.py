# Replies with a line that is not JSON, with a terminal escape sequence in it.
import sys

for line in sys.stdin:
    print("hello, I am not JSON \x1b[31mred", flush=True)
