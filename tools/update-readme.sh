#!/usr/bin/env bash
# Regenerates the example output in README.md (between the readme-example markers) by running
# derivcheck on docs/examples/quickstart.dc. tests/docs checks that README.md matches.
# Usage: tools/update-readme.sh [path/to/derivcheck]   (default: build/derivcheck)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cli="${1:-$root/build/derivcheck}"
cd "$root"
out="$("$cli" check docs/examples/quickstart.dc || true)"
python3 - "$out" <<'PY'
import sys, re
out = sys.argv[1]
s = open("README.md").read()
block = "<!-- readme-example:begin -->\n```console\n$ derivcheck check docs/examples/quickstart.dc\n" + out + "\n```\n<!-- readme-example:end -->"
s2 = re.sub(r"<!-- readme-example:begin -->.*?<!-- readme-example:end -->", lambda m: block, s, flags=re.S)
open("README.md.tmp", "w").write(s2)
PY
mv README.md.tmp README.md
