#!/usr/bin/python3
"""Put the output of `peloid keys` between the KEYS markers of README.md.

usage: tools/readme_keys.py BIN README        (rewrites README in place)
       tools/readme_keys.py BIN README --check (exit 1 if README is stale)
"""
import subprocess
import sys

BEGIN, END = "<!-- BEGIN KEYS -->", "<!-- END KEYS -->"


def main():
    binary, readme = sys.argv[1], sys.argv[2]
    keys = subprocess.run([binary, "keys"], check=True, capture_output=True, text=True).stdout
    text = open(readme, encoding="utf-8").read()
    head, rest = text.split(BEGIN, 1)
    _, tail = rest.split(END, 1)
    new = head + BEGIN + "\n" + keys.strip("\n") + "\n" + END + tail
    if "--check" in sys.argv:
        if new != text:
            print("README.md scene-key reference is stale: run `make readme`", file=sys.stderr)
            return 1
        return 0
    open(readme, "w", encoding="utf-8").write(new)
    return 0


if __name__ == "__main__":
    sys.exit(main())
