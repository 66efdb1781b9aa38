#!/usr/bin/env bash
# The source tree's shape (issue 46, STYLE.md "one concern per file"): no C
# file or header in src/ and kernels/ over 600 lines.  A file that grows past
# it is split by concern, not trimmed.  Fails naming every file over the bound.
# Usage: bash tests/cli/source_tree.sh [BIN] (BIN unused: make check passes it)
set -u
cd "$(dirname "$0")/../.."
MAX=600
over=$(find src kernels -name '*.[ch]' -print0 | xargs -0 wc -l | awk -v max=$MAX '$2 != "total" && $1 > max {print $2 " (" $1 " lines)"}')
n=$(find src kernels -name '*.[ch]' | wc -l)
if [ -n "$over" ]; then
    echo "FAIL source_tree: files over $MAX lines in src/ and kernels/:"
    echo "$over" | sed 's/^/  /'
    exit 1
fi
echo "ok source_tree: $n files in src/ and kernels/, none over $MAX lines"
