#!/usr/bin/env python3
"""An independent implementation of a variant's numbers (labs/exercises/variant.hpp), for the golden
values of test_variants.cpp: FNV-1a (64 bits) of the ID's UTF-8 bytes, mixed with the base seed and
read through SplitMix64.

  variant_numbers.py ID BASE        prints seed(BASE) and the stream's first two uniform(0, 90)
"""
import sys

MASK = (1 << 64) - 1


def fnv1a(text):
    value = 0xcbf29ce484222325
    for byte in text.encode("utf-8"):
        value = ((value ^ byte) * 0x100000001b3) & MASK
    return value


def splitmix64(state):
    state = (state + 0x9e3779b97f4a7c15) & MASK
    z = state
    z = ((z ^ (z >> 30)) * 0xbf58476d1ce4e5b9) & MASK
    z = ((z ^ (z >> 27)) * 0x94d049bb133111eb) & MASK
    return state, z ^ (z >> 31)


def stream_state(variant_id, base):
    state, _ = splitmix64(fnv1a(variant_id) ^ ((base * 0xd1b54a32d192ed03) & MASK))
    return state


def seed(variant_id, base):
    _, value = splitmix64(stream_state(variant_id, base))
    mixed = value >> 32
    return mixed + 1 if mixed == base else mixed


def uniforms(variant_id, base, low, high, count):
    state, values = stream_state(variant_id, base), []
    for _ in range(count):
        state, value = splitmix64(state)
        values.append(low + (high - low) * ((value >> 11) * 2.0 ** -53))
    return values


if __name__ == "__main__":
    variant_id, base = sys.argv[1], int(sys.argv[2])
    print(seed(variant_id, base), *(repr(u) for u in uniforms(variant_id, base, 0.0, 90.0, 2)))
