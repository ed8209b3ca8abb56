#!/usr/bin/env python3
"""A linkage solution that ignores its variant (tests/exercises/variants/linkage_variants.py): the
generic reference with the file's model in place of the request's, as a student who typed in
TASK.md's numbers without a variant would answer.

  file_numbers.py record MODEL_JSON   the reference; saves the first request's model to MODEL_JSON
  file_numbers.py use MODEL_JSON      the reference, with MODEL_JSON's model in every request
"""
import json
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "references", "python"))
import linkage  # noqa: E402


def main():
    mode, path = sys.argv[1], sys.argv[2]
    model = None
    if mode == "use":
        with open(path, encoding="utf-8") as saved:
            model = json.load(saved)
    for line in sys.stdin:
        if not line.strip():
            continue
        request = json.loads(line)
        if mode == "record" and not os.path.exists(path):
            with open(path, "w", encoding="utf-8") as out:
                json.dump(request["model"], out)
        if model is not None:
            request["model"] = model
        try:
            reply = dict(linkage.solve(request))
            reply["id"] = request.get("id")
            text = json.dumps(reply, default=linkage.to_json)
        except Exception as error:
            text = json.dumps({"id": request.get("id"), "error": f"{type(error).__name__}: {error}"})
        print(text, flush=True)


if __name__ == "__main__":
    main()
