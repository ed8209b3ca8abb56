# Never reads, never replies, never exits by itself.
import time

while True:
    time.sleep(1000)
