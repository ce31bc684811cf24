#!/usr/bin/env python3
"""Plant a slip in each derived row of a Markdown document and see whether it is refuted there.

Usage: tools/plant-slips.py BINARY DOCUMENT.md

For every relation that `BINARY check --json DOCUMENT` proves (not an identity), the side of
that relation in the row's text is changed once, by the first of: `+` -> `-`, a factor `2` ->
`3`, `-` -> `+`, `m_1` -> `m_2`; the changed document is checked again, and the verdict at that
row and link is printed. A mutation can leave the relation true (the limit of 2 m_1 v_1 /
(m_1 - m_2) is still 0); such rows show as proved. Prints one line per planted slip and the
count refuted at their link and at their row (any of its links). docs/documents.md has the figures for the seed handout.
"""
import json
import os
import re
import subprocess
import sys
import tempfile


def check(binary, path):
    out = subprocess.run([binary, 'check', path, '--json'], capture_output=True, text=True).stdout
    d = json.loads(out)
    return {(r['line'], r['col'], r['link']): r for f in d['files'] for r in f['steps']}


def mutate(seg):
    for pat, rep in [(r'\+', '-'), (r'(?<![\^_{\d])2(?![\d}])', '3'), (r'(?<![\^_{])-', '+'), (r'm_1', 'm_2')]:
        m = re.search(pat, seg)
        if m:
            return seg[:m.start()] + rep + seg[m.end():]
    return None


def main():
    if len(sys.argv) != 3:
        print(__doc__)
        return 2
    binary, src = sys.argv[1], sys.argv[2]
    text = open(src).read().split('\n')
    base = check(binary, src)
    proved = sorted(k for k, r in base.items()
                    if r['verdict'] == 'proved' and r.get('rule') != 'identity' and r['label'][0] == 'L')
    planted = refuted = refuted_row = 0
    with tempfile.TemporaryDirectory() as tmp:
        for (line, col, link) in proved:
            # the row's own text: from its first math character to the end of the row
            row = re.split(r'\\\\|\$\$|\\end\{', text[line - 1][col - 1:])[0]
            parts = re.split(r'(?<![<>\\])=', row)
            if len(parts) < 2:
                continue
            idx = len(parts) - 1 if link == 0 else min(link, len(parts) - 1)
            core = re.split(r'\\quad|\$\$|\\\\|\\tag', parts[idx])[0]
            changed = mutate(core)
            if changed is None:
                continue
            parts[idx] = parts[idx].replace(core, changed, 1)
            lines = list(text)
            lines[line - 1] = text[line - 1][:col - 1] + text[line - 1][col - 1:].replace(row, '='.join(parts), 1)
            path = os.path.join(tmp, os.path.basename(src))
            open(path, 'w').write('\n'.join(lines))
            got = check(binary, path)
            r = got.get((line, col, link), {})
            # the row is refuted when one of its links is: a slip in the middle side of
            # `v'_1 = A = B` makes A = B false as well as v'_1 = A
            row_refuted = any(v.get('verdict') == 'refuted' for (l, c, _), v in got.items() if (l, c) == (line, col))
            planted += 1
            refuted += r.get('verdict') == 'refuted'
            refuted_row += row_refuted
            print('%d:%d:%d  %-9s %-4s  %s -> %s  %s' % (line, col, link, r.get('verdict', 'missing'),
                                                      'row' if row_refuted else '', core.strip()[:50],
                                                      changed.strip()[:50], r.get('reason', '')[:110]))
    print('refuted %d of %d planted slips at their link, %d at their row' % (refuted, planted, refuted_row))
    return 0


if __name__ == '__main__':
    sys.exit(main())
