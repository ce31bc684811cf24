#!/usr/bin/env python3
"""Writes a generated claim bank of N lines (for throughput and memory measurements; see
docs/performance.md): the claims of tests/data/corpus.jsonl and tests/data/adversarial.jsonl
taken in turn, each with a fresh id, so the mix of kinds, true and false claims and costs is
that of the two corpora.

    tools/gen-claim-bank.py 100000 > bank.jsonl
"""
import json
import pathlib
import sys

root = pathlib.Path(__file__).resolve().parent.parent
n = int(sys.argv[1]) if len(sys.argv) > 1 else 100000
templates = []
for name in ("corpus.jsonl", "adversarial.jsonl"):
    for line in (root / "tests" / "data" / name).read_text().splitlines():
        if line.strip():
            templates.append(json.loads(line))
out = sys.stdout
for i in range(n):
    c = dict(templates[i % len(templates)])
    c["id"] = f"{c.get('id', 'claim')}#{i // len(templates)}"
    out.write(json.dumps(c, separators=(",", ":")) + "\n")
